"""[Efe2014]'s identification procedures on records of the virtual rig: friction (eqs. 4.24-4.25 and the
Stribeck law, eq. 3.47), internal leakage from a locked piston (section 4.5.5), and the valve's K(x_v) and
H(x_v, d_f) (sections 5.1.2-5.1.3)."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.components.signals import Table
from hydroservo.errors import ParameterError
from hydroservo.identification.flow_coefficient import flow_coefficient_tables
from hydroservo.identification.friction import fit_stribeck, friction_from_record
from hydroservo.identification.leakage import leakage_from_record
from hydroservo.identification.records import Channel, Record
from hydroservo.identification.rig import EFE_SENSORS, Sensor, held_steps, triangle, virtual_rig
from hydroservo.laws.friction import stribeck

LOGGED = ("cyl.pA", "cyl.pB", "load.x", "command.y")


def _logged(system, t_end, seed, params=None, name=None):
    return virtual_rig(system, {s: EFE_SENSORS[s] for s in LOGGED}, t_end=t_end, seed=seed, params=params, name=name)


def test_table_5_2_refit_from_its_experimental_column() -> None:
    # Efe2014 Table 5.2: six experimental forces; the thesis's law (c_s 0.01, F_v 280, F_c0 78, F_s0 5) misses
    # them by up to 3.55 %. A least-squares fit of the same law can only do as well or better, and its viscous
    # and Coulomb terms must agree with the thesis's within their standard errors.
    v = [0.165, 0.123, 0.078, 0.048, 0.022, 0.01]
    f = [120.53, 113.7, 103.52, 94.75, 85.3, 79.86]
    fit = fit_stribeck(v, f)
    assert np.max(np.abs(fit.relative_error)) <= 3.55
    assert abs(fit.parameters["B"] - 280.0) < 2 * fit.stderr["B"]
    assert abs(fit.parameters["F_c0"] - 78.0) < 2 * fit.stderr["F_c0"]
    # the slowest speed is the thesis's own c_s: the static term cannot be pinned down, and the fit says so
    assert any("F_s0" in w for w in fit.warnings) and any("c_s" in w for w in fit.warnings)
    thesis = stribeck(np.array(v), 280.0, 78.0, 5.0, 0.01)
    np.testing.assert_allclose(100 * (np.array(f) - thesis) / np.array(f), [-3.04, 1.11, 3.55, 3.45, 0.69, -3.48], atol=0.005)


def test_fit_stribeck_refuses_bad_points() -> None:
    with pytest.raises(ParameterError, match="at least two"):
        fit_stribeck([0.1], [100.0])
    with pytest.raises(ParameterError, match="opposing it"):
        fit_stribeck([0.1, -0.1], [100.0, 100.0])


@pytest.fixture(scope="module")
def friction_record():
    arm = hs.load_model("robot-arm")
    levels = [s * u for u in (0.2, 0.25, 0.3, 0.4, 0.5, 0.6) for s in (1, -1)]
    times, values = held_steps(levels, 0.6, rest=0.2)
    arm.replace(Table("command", times=times, values=values))
    return arm, _logged(arm, times[-1], seed=1, name="friction")


def test_friction_from_a_record_follows_the_law_it_came_from(friction_record) -> None:
    arm, record = friction_record
    points = friction_from_record(arm, record)
    assert len(points) == 12 and points.velocity.min() < 0 < points.velocity.max()
    law = stribeck(points.velocity, 280.0, 78.0, 5.0, 0.01, 1e-4)  # the model's friction (Table 5.2's parameters)
    # eq. 4.24 on 0.05 bar pressures over 8 cm^2 (4 N a sample) averaged over ~14 samples: within 4 % of the law
    np.testing.assert_allclose(points.force, law, rtol=0.04)
    fit = fit_stribeck(points.velocity, points.force)
    assert fit.parameters["B"] == pytest.approx(280.0, rel=0.15)
    assert fit.parameters["F_c0"] == pytest.approx(78.0, rel=0.05)


#: the example records' truth (docs/calibration.md): the published arm with these friction terms
RIG_FRICTION = {"load.B": 350.0, "load.F_c0": 60.0}


@pytest.fixture(scope="module")
def clean_friction_record(friction_record):
    """The twelve held speeds of ``friction_record`` with the example records' friction, logged without noise
    (noise is drawn onto it in the tests: one simulation for every draw)."""
    arm, record = friction_record
    sensors = {s: Sensor(EFE_SENSORS[s].rate, EFE_SENSORS[s].unit) for s in LOGGED}
    return arm, virtual_rig(arm, sensors, t_end=record.span[1], params=RIG_FRICTION, name="clean")


def _with_noise(record, scale, rng):
    """``record`` with the Gaussian noise of Efe's logger (0.05 bar, 0.02 mm) times ``scale`` drawn onto it."""
    sd = {"cyl.pA": 0.05, "cyl.pB": 0.05, "load.x": 0.02}
    return Record(record.name, {n: Channel(n, c.t, c.values + rng.normal(0.0, scale * sd.get(n, 0.0), c.values.size), c.unit, "test")
                                for n, c in record.channels.items()})


def _fit(arm, record):
    points = friction_from_record(arm, record)
    return points, fit_stribeck(points.velocity, points.force, held={"F_s0": 5.0, "c_s": 0.01})  # the model's own


def test_friction_points_are_eq_4_25_averages_on_a_noise_free_record(clean_friction_record) -> None:
    # Without noise the rod moves steadily in every hold after its transient: the forces must be eq. 4.25's plain
    # averages, and the law (its static term held at the truth) must give back the truth. The former centred 50 ms
    # window over the whole record saw each hold's end and gave B = 371.9 (6 %) and F_c0 = 60.6 here.
    arm, record = clean_friction_record
    points, fit = _fit(arm, record)
    A_A, A_B = arm["cyl"].values["A_A"], arm["cyl"].values["A_B"]
    pa, pb, x = record["cyl.pA"], record["cyl.pB"], record["load.x"]
    for (start, end), force, v in zip(points.intervals, points.force, points.velocity):
        sel, held = (pa.t >= start) & (pa.t <= end), (x.t >= start) & (x.t <= end)
        plain = np.mean(pa.to("Pa")[sel] * A_A - pb.to("Pa")[sel] * A_B)  # eq. 4.25
        assert force == pytest.approx(plain, abs=0.01)  # N: what is left of the acceleration in a steady hold
        assert v == pytest.approx(np.polyfit(x.t[held], x.to("m")[held], 1)[0], rel=1e-4)
    assert fit.parameters["B"] == pytest.approx(350.0, rel=1e-3)
    assert fit.parameters["F_c0"] == pytest.approx(60.0, rel=1e-3)


@pytest.mark.parametrize("scale", [0.5, 1.0, 2.0])
def test_friction_is_unbiased_at_three_noise_levels(clean_friction_record, scale) -> None:
    # Forty records at each noise level (half, once and twice the example records'). An unbiased procedure puts the
    # mean of its estimates within a fraction of one record's standard error of the truth: the bound 0.5 SE is
    # three standard errors of a mean of forty (SE / 6.3) with room to spare. The former procedure's bias was two
    # standard errors at the examples' noise (B = 378 ± 13 on average). The standard errors must also be honest:
    # about 68 % of the records within one of the truth, at least half of them here (forty draws: 0.68 ± 0.07).
    arm, record = clean_friction_record
    rng = np.random.default_rng(37)
    fits = [_fit(arm, _with_noise(record, scale, rng))[1] for _ in range(40)]
    for key, truth in (("B", 350.0), ("F_c0", 60.0)):
        values = np.array([f.parameters[key] for f in fits])
        se = np.array([f.stderr[key] for f in fits])
        assert abs(values.mean() - truth) < 0.5 * se.mean(), (key, values.mean(), se.mean())
        assert np.mean(np.abs(values - truth) < se) >= 0.5, key


def _locked(C_Li, signal, t_end):
    """The piston held at its stroke end, the valve opened to ``signal`` (overlap 10 %) at 0.1 s and held."""
    arm = hs.load_model("robot-arm")
    arm.set("load.x0", "295 mm")
    arm.replace(Table("command", times=[0, 0.1, 0.105, t_end], values=[0, 0, signal, signal]))
    return arm, _logged(arm, t_end, seed=2, params={"cyl.C_Li": C_Li})


@pytest.mark.parametrize("C_Li", [1e-13, 1e-12])
def test_leakage_from_a_locked_piston(C_Li) -> None:
    # The valve a little open towards A (15 %, overlap 10 %): chamber A settles below the supply by the leakage's
    # pressure drop. The balance recovers the truth with the model's own valve law either way; how much that law
    # decides it is the law sensitivity: 0.2 % at 1e-12 (the edge drops 2.1 bar, 12 times the law's laminar
    # transition of 0.18 bar), 61 % at 1e-13 (0.075 bar, below the transition), which a warning names.
    arm, record = _locked(C_Li, 0.15, 3.0)
    est = leakage_from_record(arm, record)
    assert abs(est.value - C_Li) < 3 * est.stderr
    assert est.stderr < 0.1 * C_Li
    assert est.from_b == pytest.approx(C_Li, rel=0.1)
    assert est.transition == pytest.approx(0.178e5, rel=0.01)
    if C_Li == 1e-12:
        assert abs(est.law_sensitivity) < 0.01 and est.edge_drop > 10 * est.transition
        assert not est.warnings
    else:
        assert est.law_sensitivity > 0.5 and est.edge_drop < est.transition
        assert len(est.warnings) == 1 and "laminar transition moves C_Li by +6" in est.warnings[0]


def test_leakage_law_sensitivity_and_the_operating_point_that_removes_it() -> None:
    # Issue 37: the example's locked-piston test (C_Li 3e-13, 15 %) runs the supply edge at 0.29 bar, 1.6 times the
    # laminar transition: the plain turbulent law gives C_Li 8.6 % higher; reported and warned. A smaller opening
    # (12 %) raises the drop to 7 times the transition, where the laws agree within 1 % and no warning is given,
    # but fills chamber A slowly: held 3 s it is not settled (said so, and the answer is 50 % off), held 10 s
    # it is, and the truth comes back within three standard errors.
    arm, record = _locked(3e-13, 0.15, 3.0)
    est = leakage_from_record(arm, record)
    assert est.law_sensitivity == pytest.approx(0.086, abs=0.005)
    assert est.turbulent == pytest.approx(3e-13 * (1 + est.law_sensitivity), rel=0.02)
    assert est.edge_drop / est.transition == pytest.approx(1.6, abs=0.1)
    assert any("laminar transition moves C_Li by +8.6 %" in w for w in est.warnings)
    assert est.to_dict()["law_sensitivity"]["relative_change_percent"] == pytest.approx(8.6, abs=0.5)
    arm, record = _locked(3e-13, 0.12, 3.0)
    est = leakage_from_record(arm, record)
    assert any("still changing" in w for w in est.warnings) and abs(est.value / 3e-13 - 1) > 0.3
    arm, record = _locked(3e-13, 0.12, 10.0)
    est = leakage_from_record(arm, record)
    assert abs(est.law_sensitivity) < 0.01 and est.edge_drop > 5 * est.transition
    assert abs(est.value - 3e-13) < 3 * est.stderr
    assert not est.warnings


def test_leakage_needs_both_chamber_pressures() -> None:
    arm = hs.load_model("robot-arm")
    record = virtual_rig(arm, {"cyl.pA": EFE_SENSORS["cyl.pA"], "command.y": EFE_SENSORS["command.y"]}, t_end=0.5)
    with pytest.raises(ParameterError, match="needs both chamber pressures"):
        leakage_from_record(arm, record)


# slow: four slow sweeps of the robot arm; the other rig procedures stay in the default suite
@pytest.mark.slow
def test_flow_coefficient_and_hysteresis_recovered() -> None:
    # The robot arm's valve has K(x_v) (1 between 20 and 50 % of the stroke, less outside) and 5 % less flow
    # while closing (H_closing 0.95): slow sweeps up and down, extending and retracting, recover both.
    arm = hs.load_model("robot-arm")
    records = []
    for sign, x0 in ((1, "20 mm"), (-1, "280 mm")):
        swept = arm.copy()
        swept.set("load.x0", x0)
        times, values = triangle(sign * 0.75, 3.0)
        swept.replace(Table("command", times=times, values=values))
        records.append(_logged(swept, times[-1], seed=4, name=f"sweep{sign:+d}"))
    result = flow_coefficient_tables(arm, records)
    K = dict(zip(result.tables["K_x"], result.tables["K"]))
    truth = arm["valve"].tables
    for x, k in K.items():
        if 0.25 <= abs(x) <= 0.7:  # away from the laps (10 % overlap), where a small flow is a large ratio error
            assert k == pytest.approx(float(np.interp(x, truth["K_x"], truth["K"])), abs=0.03), x
    H = [h for x, h in zip(result.tables["H_x"], result.tables["H_closing"]) if 0.25 <= abs(x) <= 0.7]
    assert np.median(H) == pytest.approx(0.95, abs=0.01)
    assert all(abs(h - 0.95) < 0.05 for h in H)


def test_identify_friction_on_the_example_record_is_within_one_standard_error() -> None:
    # The shipped example record (docs/calibration.md; truth B 350 N s/m, F_c0 60 N), read by the command's
    # workflow: before, B = 366.6 ± 12.1 and F_c0 = 61.43 ± 0.71 (F_c0 two standard errors off). The static term is
    # not determined by speeds above 0.02 m/s: held at the model's own values, named, and not written.
    from importlib.resources import files

    from hydroservo.workflows.identify import IdentifyFriction

    folder = files("hydroservo") / "data" / "examples"
    report = IdentifyFriction("robot-arm", [[str(folder / "arm_friction-200Hz.csv"), str(folder / "arm_friction-40Hz.csv")]]).run()
    fit = report.fit
    for key, truth in (("B", 350.0), ("F_c0", 60.0)):
        assert abs(fit.parameters[key] - truth) < fit.stderr[key], (key, fit.parameters[key], fit.stderr[key])
    assert fit.held == {"F_s0": 5.0, "c_s": 0.01}
    assert any("held at the model's own values" in w for w in report.warnings)
    written = report.parameter_file()
    assert "\nB = " in written and "\nF_c0 = " in written and "\nF_s0 = " not in written and "\nc_s = " not in written
