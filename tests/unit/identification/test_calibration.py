"""Calibration of a system against rig records: recovery of known parameters, exact gradients, uncertainty,
identifiability warnings, failures handled, prediction on held-out records and experiment design."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.errors import ParameterError, SolverError
from hydroservo.identification.calibration import _Problem, calibrate, parse_fit, plan_experiment, predict, prepare
from hydroservo.identification.records import Record
from hydroservo.identification.rig import Sensor, virtual_rig
from hydroservo.system.integration import SolverSettings

FIVE = ["spool.tau", "valve.c_v", "cyl.C_Li", "load.B", "load.F_c0"]
NOISE = {"cyl.pA": "0.05 bar", "cyl.pB": "0.05 bar", "load.x": "0.02 mm"}


@pytest.fixture(scope="module")
def five(step_record: Record, stepped_arm):
    return calibrate(stepped_arm(), [step_record], FIVE, inputs=["command.y"], noise=NOISE)


def test_five_parameters_recovered_within_their_intervals(five, arm_truth) -> None:
    # The record comes from the model with ARM_TRUTH, at Efe2014 Table 5.1's rates (40 and 200 Hz) with 0.05 bar
    # and 0.02 mm noise; the fit starts from the published robot arm, 20-50 % away on every parameter.
    assert five.success
    for k, p in enumerate(five.parameters):
        lo, hi = five.ci95[k]
        assert lo <= arm_truth[p.name] <= hi, (p.name, arm_truth[p.name], lo, hi)
        assert five.stderr[k] < 0.05 * arm_truth[p.name]  # the record determines each to better than 5 %
    # residuals at the noise that made the record: a model that explains it
    for s in five.signals:
        assert 0.85 < s.rms / s.noise < 1.15, s
    assert not [w for w in five.warnings if "RMS residual" in w]


def test_values_reported_in_the_users_units(five) -> None:
    d = five.to_dict()
    assert d["parameters"]["spool.tau"]["unit"] == "ms"  # the model file gives "30 ms"
    assert 23.0 < d["parameters"]["spool.tau"]["value"] < 25.0
    lo, hi = d["parameters"]["spool.tau"]["ci95"]
    assert lo < d["parameters"]["spool.tau"]["value"] < hi
    assert d["signals"]["load.x"]["unit"] == "mm" and d["signals"]["cyl.pA"]["unit"] == "bar"
    assert set(d["correlation"]) == set(FIVE)
    assert d["correlation"]["load.B"]["load.B"] == pytest.approx(1.0)
    assert d["evaluations"]["gradient"] == "exact"
    assert five.system["spool"].given["tau"].endswith(" ms")  # the calibrated system keeps the user's unit


def test_correlation_is_symmetric_and_bounded(five) -> None:
    c = five.correlation
    np.testing.assert_allclose(c, c.T, atol=1e-12)
    assert np.all(np.abs(c) <= 1 + 1e-9)


def _problem(system, record, fit, inputs=(), accuracy=1e-10):
    exps = [prepare(system, record, inputs, initial="model")]
    sigma = {n: 1.0 for n in exps[0].measured}
    return _Problem(exps, parse_fit(system, fit), sigma, SolverSettings.of(accuracy=accuracy, max_steps=10_000_000))


def _richardson(problem, theta, k, h):
    e = np.zeros(theta.size)
    e[k] = h
    wide = (problem.residuals(theta + e) - problem.residuals(theta - e)) / (2 * h)
    narrow = (problem.residuals(theta + e / 2) - problem.residuals(theta - e / 2)) / h
    return (4 * narrow - wide) / 3


@pytest.mark.parametrize(
    ("model", "sensors", "fit", "t_end"),
    [
        ("robot-arm", {"cyl.pA": Sensor(40, "bar"), "load.x": Sensor(200, "mm")}, ["spool.tau", "valve.c_v", "load.B"], 0.55),
        ("flight-simulator", {"load.x": Sensor(1000, "in"), "cyl.pA": Sensor(500, "psi")}, ["cyl.beta_e", "load.B", "spool.K2"], 0.3),
    ],
)
def test_exact_gradients_match_central_differences(model, sensors, fit, t_end) -> None:
    # Central differences with Richardson extrapolation (error O(h^4)) on runs integrated to 1e-10: the best of
    # three step sizes agrees with the sensitivity equations to 1e-6 of the column's norm (the figure).
    system = hs.load_model(model)
    record = virtual_rig(system, sensors, t_end=t_end, seed=0)
    problem = _problem(system, record, fit)
    theta = problem.start() + 0.01
    J = problem.jacobian(theta)
    for k in range(theta.size):
        best = min(np.linalg.norm(J[:, k] - _richardson(problem, theta, k, h)) / np.linalg.norm(J[:, k])
                   for h in (2e-3, 1e-3, 5e-4))
        assert best < 1e-6, (fit[k], best)


def test_noise_estimated_when_not_given(step_record, stepped_arm) -> None:
    cal = calibrate(stepped_arm(), [step_record], FIVE, inputs=["command.y"], initial="model")
    by = {s.name: s for s in cal.signals}
    assert not by["load.x"].noise_given
    # the estimate from the residuals is the noise the rig added (0.02 mm, 0.05 bar), within 15 %
    assert by["load.x"].noise == pytest.approx(0.02, rel=0.15)
    assert by["cyl.pA"].noise == pytest.approx(0.05, rel=0.15)
    assert cal.to_dict()["signals"]["load.x"]["noise_given"] is False


def test_parameters_the_records_cannot_separate_are_named(stepped_arm, make_arm_record) -> None:
    # One extension at one speed: viscous and Coulomb friction enter as B v + F_c0, so the record fixes that
    # sum well and the split between them hardly at all.
    from hydroservo.identification.rig import EFE_SENSORS

    arm = stepped_arm(levels=(0.368,), t_end=1.2)
    record = virtual_rig(arm, {s: EFE_SENSORS[s] for s in ("cyl.pA", "cyl.pB", "load.x", "command.y")}, seed=1, t_end=1.2)
    cal = calibrate(arm, [record], ["load.B", "load.F_c0"], inputs=["command.y"], noise=NOISE, initial="model")
    named = [w for w in cal.warnings if "load.B" in w and "load.F_c0" in w]
    assert len(named) == 1 and "what they determine is load.B^" in named[0], cal.warnings
    assert abs(cal.correlation[0, 1]) > 0.95


def test_a_failing_trial_point_is_a_rejected_step(step_record, stepped_arm, monkeypatch) -> None:
    from hydroservo.identification.calibration import _solve

    problem = _problem(stepped_arm(), step_record, ["spool.tau"], ["command.y"], accuracy=1e-6)

    def fails(e, theta):
        raise SolverError("integration of 'robot-arm' failed at t = 0.6 s: the step budget was used up")

    monkeypatch.setattr(problem, "simulate", fails)
    r = problem.residuals(problem.start())
    assert r.shape == (problem.size,) and np.all(np.isnan(r))  # NaN: SciPy's trust region shrinks, no crash
    with pytest.raises(SolverError, match="cannot be integrated at the starting values"):
        _solve(problem, problem.start(), "exact", 10)


def test_bad_fit_requests_are_refused(stepped_arm) -> None:
    arm = stepped_arm()
    with pytest.raises(ParameterError, match=r"'spool.tua' is not a parameter of 'robot-arm'; did you mean spool.tau"):
        parse_fit(arm, ["spool.tua"])
    with pytest.raises(ParameterError, match="lower bound must be below the upper bound"):
        parse_fit(arm, ["spool.tau=50 ms..10 ms"])
    with pytest.raises(ParameterError, match="expected bounds LO..HI"):
        parse_fit(arm, {"spool.tau": "10 ms"})
    with pytest.raises(ParameterError, match="a shared stroke cannot be fitted"):
        parse_fit(arm, ["spool.xv_max"])
    fit = parse_fit(arm, ["spool.tau=10 ms..100 ms", "load.F_c0"])
    assert fit[0].unit == "ms" and fit[0].lower == pytest.approx(0.01) and fit[0].log
    assert fit[1].unit == "N" and fit[1].lower == pytest.approx(0.78)


@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_several_starts_run_together(step_record, stepped_arm) -> None:
    cal = calibrate(stepped_arm(), [step_record], ["load.B", "spool.tau"], inputs=["command.y"], noise=NOISE,
                    initial="model", starts=3, seed=1)
    assert len(cal.starts) == 3
    costs = [s["cost"] for s in cal.starts if s["cost"] is not None]
    assert cal.cost == pytest.approx(min(costs), rel=1e-6) or cal.cost <= min(costs)


def test_gradient_beats_finite_differences_in_evaluations(stepped_arm, make_arm_record) -> None:
    fit = {"load.B": 350.0, "valve.c_v": 1.3e-4, "spool.tau": 0.024}
    record = make_arm_record(7, params=fit)  # only the fitted parameters differ from the model's
    exact = calibrate(stepped_arm(), [record], list(fit), inputs=["command.y"], noise=NOISE, initial="model")
    fd = calibrate(stepped_arm(), [record], list(fit), inputs=["command.y"], noise=NOISE, initial="model",
                   gradient="finite-differences")
    # forward differences cost one run per parameter per Jacobian; the sensitivities one (larger) run
    assert exact.nfev + exact.njev < fd.nfev
    assert np.all(np.abs(exact.values - fd.values) < 0.2 * exact.stderr)  # the same optimum
    for k, name in enumerate(fit):  # one noise draw: the truth within three standard errors (coverage: slow test)
        assert abs(exact.values[k] - fit[name]) < 3 * exact.stderr[k]


def test_prediction_of_a_held_out_record(stepped_arm, arm_truth, make_arm_record) -> None:
    held_out = make_arm_record(11)
    truth = stepped_arm()
    for k, v in arm_truth.items():
        truth.set(k, v)
    good = predict(truth, [held_out], inputs=["command.y"]).to_dict()[held_out.name]
    assert good["load.x"]["rms"] < 0.03  # mm: the noise (0.02 mm) and little more
    assert good["load.x"]["class"] == "accurate"
    published = predict(stepped_arm(), [held_out], inputs=["command.y"]).to_dict()[held_out.name]
    assert published["load.x"]["rms"] > 5 * good["load.x"]["rms"]


def test_plan_agrees_with_the_fit_it_plans(five, step_record, stepped_arm, arm_truth) -> None:
    # The Fisher information of a noise-free planned record at the true values predicts the standard errors a
    # fit of the noisy record gets (both are J^T J at nearly the same point): within 20 %.
    truth = stepped_arm()
    for k, v in arm_truth.items():
        truth.set(k, v)
    planned = virtual_rig(truth, {n: Sensor(c.rate, c.unit) for n, c in step_record.channels.items()}, t_end=4.0)
    plan = plan_experiment(truth, [planned], FIVE, NOISE, inputs=["command.y"])  # initial states estimated, as the fit
    np.testing.assert_allclose(plan.stderr, five.stderr, rtol=0.2)
    with pytest.raises(ParameterError, match="a plan needs every signal's sensor noise"):
        plan_experiment(truth, [planned], FIVE, {"load.x": "0.02 mm"}, inputs=["command.y"])


def test_trimmed_initial_states_have_exact_derivatives(stepped_arm) -> None:
    # Only the pressures are logged: the rod position and speed and the spool start in equilibrium with them
    # (trim, measured states held). Their derivatives come by the implicit-function theorem; central differences
    # (Richardson, runs to 1e-10) agree.
    arm = stepped_arm(t_end=0.55)
    record = virtual_rig(arm, {"cyl.pA": Sensor(40, "bar"), "cyl.pB": Sensor(40, "bar")}, t_end=0.55, seed=0)
    exps = [prepare(arm, record, (), initial="trim")]
    assert exps[0].trim and set(exps[0].fixed_states) == {"cyl.pA", "cyl.pB"}
    problem = _Problem(exps, parse_fit(arm, ["valve.c_v", "load.B"]), {"cyl.pA": 1.0, "cyl.pB": 1.0},
                       SolverSettings.of(accuracy=1e-10, max_steps=10_000_000))
    theta = problem.start() + 0.01
    J = problem.jacobian(theta)
    for k in range(theta.size):
        best = min(np.linalg.norm(J[:, k] - _richardson(problem, theta, k, h)) / np.linalg.norm(J[:, k])
                   for h in (2e-3, 1e-3, 5e-4))
        assert best < 1e-5, best


def test_a_recorded_supply_drives_the_model(stepped_arm) -> None:
    # supply.p logged (Table 5.1's pump outlet, 40 Hz) replaces the supply's table: the model then sees the
    # recorded pressure, here a 10 % sag the model's own table does not have
    arm = stepped_arm(t_end=1.0)
    sagging = arm.copy()
    sagging["supply"].set_table(["0 s", "0.5 s", "1 s"], ["30 bar", "27 bar", "27 bar"])
    record = virtual_rig(sagging, {"supply.p": Sensor(40, "bar"), "load.x": Sensor(200, "mm"), "command.y": Sensor(200)},
                         t_end=1.0)
    fitted = predict(arm, [record], inputs=["command.y", "supply.p"], initial="model").to_dict()[record.name]
    ignored = predict(arm, [record], inputs=["command.y"], initial="model").to_dict()[record.name]
    assert fitted["load.x"]["rms"] < 1e-3 < ignored["load.x"]["rms"]
