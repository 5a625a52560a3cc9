"""The C stepper of a model (hydroservo.codegen.c): its order, its agreement with CVODES, its C API; the
variable-step solvers every export holds (``integrate``), at the end.

Each stepper is exported and compiled once per module (about 0.3-0.6 s each); the whole module is
skipped when there is no C compiler. Deviations are stated relative to the reference signal's range
over the run (max |C - CVODES| / (max - min)); every CVODES reference runs at rtol 1e-10, atol 1e-12,
accurate to about 1e-9 of range, far below the tolerances below.
"""

from __future__ import annotations

import ctypes
import re
import subprocess
from typing import Any

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.codegen.c import CStepper, c_identifier, compiler, export_c
from hydroservo.components.base import Algebraic, Component, Param, State
from hydroservo.errors import HydroservoError, ModelError, ParameterError, SolverError
from hydroservo.system.assembly import assemble
from hydroservo.system.model import Model

try:
    compiler()
except ParameterError:
    pytest.skip("no C compiler", allow_module_level=True)


def _tight(system: hs.System, t_end: float, dt: float, **kwargs: Any) -> hs.Result:
    """CVODES at rtol 1e-10 on a grid of ``dt``."""
    return system.simulate(t_end, t_eval=np.linspace(0.0, t_end, round(t_end / dt) + 1), rtol=1e-10, atol=1e-12, method="cvodes",
                           **kwargs)  # fmt: skip


def _deviation(stepper: CStepper, t: np.ndarray, values: np.ndarray, ref: Any, name: str) -> float:
    """max |C - reference| over the reference's times, relative to the reference's range."""
    every = round((ref.t[1] - ref.t[0]) / stepper.step_size)
    column = values[::every, stepper.signals.index(name)]
    assert np.allclose(t[::every], ref.t, rtol=0, atol=1e-12)
    return float(np.max(np.abs(column - ref[name])) / np.ptp(ref[name]))


# -- a linear system with a known solution: a spring-mass driven by a sine force --------------------------
M, K, X0, F, FREQUENCY = 2.0, 800.0, 0.01, 2.0, 5.0  # [kg], [N/m], [m], [N], [Hz]


def _driven_spring() -> hs.System:
    """2 kg on 800 N/m (20 rad/s) from 10 mm at rest, pushed by 2 N at 5 Hz: the force makes the model
    time-dependent, so that the stages' times count."""
    s = hs.System("driven-spring")
    s.add(c.Mass("load", m=M, k_spring=K, x0=X0, incline=0.0))
    s.add(c.Sine("force", unit="N", amplitude=F, frequency=FREQUENCY))
    s.connect("force.y", "load.F_ext")
    return s


def _driven_spring_position(t: np.ndarray) -> np.ndarray:
    """x'' + w^2 x = (F/M) sin(W t), x(0) = X0, x'(0) = 0: the free and the forced oscillation [m]."""
    w, forced = np.sqrt(K / M), 2 * np.pi * FREQUENCY
    amplitude = F / M / (w**2 - forced**2)
    return X0 * np.cos(w * t) - forced / w * amplitude * np.sin(w * t) + amplitude * np.sin(forced * t)


@pytest.fixture(scope="module")
def spring_errors() -> dict[str, list[float]]:
    """Largest error of load.x over 1 s [m] against the closed form, per method, at h = 10 ms and 5 ms."""
    system = _driven_spring()
    errors: dict[str, list[float]] = {}
    for method in ("rk4", "bdf2"):
        for h in (0.01, 0.005):
            t, values = CStepper(system, step=h, method=method).run(1.0)
            errors.setdefault(method, []).append(float(np.max(np.abs(values[:, 0] - _driven_spring_position(t)))))
    return errors


def test_the_closed_form_is_the_models() -> None:
    ref = _tight(_driven_spring(), 1.0, 0.01)
    np.testing.assert_allclose(ref["load.x"], _driven_spring_position(ref.t), rtol=0, atol=1e-10)


@pytest.mark.parametrize(("method", "order"), [("rk4", 4), ("bdf2", 2)])
def test_observed_order(spring_errors: dict[str, list[float]], method: str, order: int) -> None:
    """Halving the step divides the error by 2^order: by 2^4.01 for rk4 and 2^1.94 for bdf2 here."""
    coarse, fine = spring_errors[method]
    assert np.log2(coarse / fine) == pytest.approx(order, abs=0.25)
    assert coarse < (3e-6 if method == "rk4" else 3e-3)  # of a 10 mm swing: the error constant, not only the order


# -- the built-in models against CVODES ---------------------------------------------------------------
@pytest.fixture(scope="module")
def flight_rk4() -> CStepper:
    return CStepper(hs.load_model("flight-simulator"), step=1e-4, method="rk4", inputs=["summer.u1"])


@pytest.fixture(scope="module")
def flight_bdf2() -> CStepper:
    return CStepper(hs.load_model("flight-simulator"), step=1e-4, method="bdf2")


@pytest.fixture(scope="module")
def servo_rk4() -> CStepper:
    return CStepper(hs.load_model("servo-solenoid-cylinder"), step=1e-4, method="rk4", inputs=["valve.u"])


@pytest.fixture(scope="module")
def flight_reference() -> hs.Result:
    return _tight(hs.load_model("flight-simulator"), 2.0, 1e-3)


FLIGHT_SIGNALS = ("y", "ydot", "p1", "p2", "xv")


def test_flight_simulator_rk4_matches_cvodes(flight_rk4: CStepper, flight_reference: hs.Result) -> None:
    """rk4 at 0.1 ms: within 1e-6 of range (measured: 1e-9 on y, 8e-8 on the pressures); bdf2 at the same
    step is 7e-6 off on p2, so the bound tells the methods apart."""
    flight_rk4.reset()
    t, values = flight_rk4.run(2.0)
    for name in FLIGHT_SIGNALS:
        assert _deviation(flight_rk4, t, values, flight_reference, name) < 1e-6, name


def test_flight_simulator_bdf2_matches_cvodes(flight_bdf2: CStepper, flight_reference: hs.Result) -> None:
    """bdf2 at 0.1 ms: within 3e-5 of range (measured: 3e-7 on y, 7e-6 on p2, about C h^2; a first-order
    method is some 1e-3 off); about two Newton iterations a step, the Jacobian kept for the whole run."""
    flight_bdf2.reset()
    t, values = flight_bdf2.run(2.0)
    for name in FLIGHT_SIGNALS:
        assert _deviation(flight_bdf2, t, values, flight_reference, name) < 3e-5, name
    stats = flight_bdf2.statistics()
    assert stats["steps"] == 20000 and stats["iterations"] < 3 * 20000 and stats["jacobians"] < 20


def test_servo_solenoid_rk4_matches_cvodes(servo_rk4: CStepper) -> None:
    """rk4 at 0.1 ms on the rate-limited valve: within 2e-5 of range (measured: 1.5e-7 on x, 4e-6 on the
    spool velocity). The position reference steps at 10 ms, on a step boundary: the step ending there
    sees the old reference (the model is evaluated on [t0, t1)), else that step alone costs 1e-3."""
    ref = _tight(hs.load_model("servo-solenoid-cylinder"), 0.4, 1e-3)
    servo_rk4.reset()
    t, values = servo_rk4.run(0.4)
    for name in ("x_mm", "cyl.pA", "cyl.pB", "load.v", "valve.s", "valve.v"):
        assert _deviation(servo_rk4, t, values, ref, name) < 2e-5, name


def test_input_adds_to_the_signal_that_drives_it(flight_rk4: CStepper) -> None:
    """0.5 V on summer.u1, added to the 2 V command step, is the run with a 2.5 V step."""
    ref = _tight(hs.load_model("flight-simulator"), 0.5, 1e-3, params={"source.amplitude": "2.5 V"})
    flight_rk4.reset()
    flight_rk4.set_input("summer.u1", "500 mV")
    assert flight_rk4.input("summer.u1") == 0.5
    t, values = flight_rk4.run(0.5)
    for name in ("y", "p1", "p2"):
        assert _deviation(flight_rk4, t, values, ref, name) < 1e-6, name
    flight_rk4.reset()
    flight_rk4.set_input("summer.u1", 0.0)
    np.testing.assert_array_equal(flight_rk4.run(0.5, inputs={"summer.u1": "0.5 V"})[1], values)
    flight_rk4.set_input("summer.u1", 0.0)


def test_stepper_refuses_unknown_names_and_partial_steps(flight_rk4: CStepper) -> None:
    with pytest.raises(ParameterError, match=r"input 'valve\.xv': not one of the stepper's inputs \(summer\.u1\)"):
        flight_rk4.set_input("valve.xv", 0.1)
    with pytest.raises(ParameterError, match="a positive whole number of steps of 0.0001 s"):
        flight_rk4.run(1.5e-4)
    with pytest.raises(ParameterError, match="expected one value, or 10 values"):
        flight_rk4.run(1e-3, inputs={"summer.u1": [0.1, 0.2]})


def test_input_matches_the_perturbed_model_under_cvodes(servo_rk4: CStepper) -> None:
    """valve.u + 0.05 in C against CVODES on the same perturbed assembly (the input last in p), and an
    input given per step as an array is the same run. Within 1e-4 of range: the spool now meets its hard
    acceleration limit (a kink in the rates, crossed inside a step) at other times than without the input;
    measured 3e-5 on the pressures and the spool, 1.5e-6 on the position, ten times less at half the step."""
    system = hs.load_model("servo-solenoid-cylinder")
    model = Model(assemble(system, perturbed=("valve.u",)))
    assert model.parameter_names[-1] == "d(valve.u)"
    p = np.append(system.parameter_vector(), 0.05)
    ref = model.simulate(0.2, p, t_eval=np.linspace(0.0, 0.2, 201), rtol=1e-10, atol=1e-12, method="cvodes")
    servo_rk4.reset()
    servo_rk4.set_input("valve.u", 0.05)
    t, held = servo_rk4.run(0.2)
    for name in ("x_mm", "cyl.pA", "valve.xs"):
        assert _deviation(servo_rk4, t, held, ref, name) < 1e-4, name
    servo_rk4.reset()
    servo_rk4.set_input("valve.u", 0.0)
    _, per_step = servo_rk4.run(0.2, inputs={"valve.u": np.full(2000, 0.05)})
    np.testing.assert_array_equal(per_step, held)
    servo_rk4.set_input("valve.u", 0.0)


def test_parameters_act_as_in_simulate(flight_rk4: CStepper) -> None:
    """load.W set through the C API (units, ranges and checks as simulate's): the same run as
    simulate(params=...), the initial full-end pressure W/A2 included once reset."""
    params = {"load.W": "3000 lbf", "cyl.beta_e": "1.2e5 psi"}
    ref = _tight(hs.load_model("flight-simulator"), 0.5, 1e-3, params=params)
    flight_rk4.set_parameters(params)
    try:
        assert flight_rk4.parameter("load.W") == pytest.approx(3000 * 4.4482216152605)
        flight_rk4.reset()
        t, values = flight_rk4.run(0.5)
        assert values[0, flight_rk4.signals.index("p2")] == pytest.approx(ref["p2"][0], rel=1e-12)
        for name in ("y", "p1", "p2"):
            assert _deviation(flight_rk4, t, values, ref, name) < 1e-6, name
        with pytest.raises(ParameterError, match="cyl.beta_e"):
            flight_rk4.set_parameter("cyl.beta_e", "-1 psi")
    finally:
        flight_rk4.set_parameters({name: hs.load_model("flight-simulator").parameter_values()[name] for name in params})


def test_names_units_and_counts_in_the_library(flight_rk4: CStepper) -> None:
    """The NULL-terminated arrays and counts a host without Python reads, as the model has them."""
    lib = ctypes.CDLL(str(flight_rk4.export.library))
    system = hs.load_model("flight-simulator")
    model = system.build()

    def strings(symbol: str) -> list[str]:
        array = (ctypes.c_char_p * 200).in_dll(lib, f"flight_simulator_{symbol}")
        found = []
        for item in array:
            if item is None:
                return found
            found.append(item.decode())
        raise AssertionError(f"{symbol} is not NULL-terminated")

    assert strings("parameter_names") == model.parameter_names
    assert strings("parameter_units") == [model.parameter_units[n] for n in model.parameter_names]
    assert strings("state_names") == model.state_names
    assert strings("state_units") == [model.units[n] for n in model.state_names]
    assert strings("output_names") == model.output_names
    assert strings("output_units") == [model.units[n] for n in model.output_names]
    assert strings("input_names") == ["summer.u1"] and strings("input_units") == ["V"]
    spec = {f"{c}.{k}": s for c, comp in system.components.items() for k, s in comp.PARAMETERS.items()}
    assert strings("parameter_descriptions") == [spec[n].description for n in model.parameter_names]
    for symbol, count in (("n_parameters", model.np), ("n_inputs", 1), ("n_states", model.nx)):
        assert ctypes.c_int.in_dll(lib, f"flight_simulator_{symbol}").value == count
    defaults = (ctypes.c_double * model.np).in_dll(lib, "flight_simulator_parameter_defaults")
    np.testing.assert_array_equal(list(defaults), system.parameter_vector())
    assert ctypes.c_double.in_dll(lib, "flight_simulator_step_size").value == 1e-4
    assert (ctypes.c_char * 8).in_dll(lib, "flight_simulator_method").value == b"rk4"
    lib.flight_simulator_find.restype = ctypes.c_int
    names = (ctypes.c_char_p * 200).in_dll(lib, "flight_simulator_output_names")
    assert lib.flight_simulator_find(names, b"p2") == model.output_names.index("p2")
    assert lib.flight_simulator_find(names, b"nothing") == -1


# -- refused steps -----------------------------------------------------------------------------------
class Blowup(Component):
    """dx/dt = x^2 from x0: x = x0 / (1 - x0 t), infinite at t = 1/x0."""

    PARAMETERS = {"x0": Param(1.0, "", "initial value")}
    STATES = {"x": State("", "the state", initial="x0")}

    def state_equations(self, t, x, u, p, y):  # type: ignore[no-untyped-def]
        return {"x": x["x"] ** 2}


class Hopeless(Component):
    """dx/dt = -z with z^2 + c + x^2 = 0: no real root for c > 0, z = sqrt(-c - x^2) for c < -x^2."""

    PARAMETERS = {"c": Param(1.0, "", "constant")}
    STATES = {"x": State("", "a state", initial=0.5)}
    ALGEBRAIC = {"z": Algebraic("", "an unknown with no solution for c > 0")}

    def state_equations(self, t, x, u, p, y):  # type: ignore[no-untyped-def]
        return {"x": -x["z"]}

    def residual_equations(self, t, x, u, p):  # type: ignore[no-untyped-def]
        return {"z": x["z"] ** 2 + p["c"] + x["x"] ** 2}

    def guess_equations(self, t, x, u, p):  # type: ignore[no-untyped-def]
        return {"z": 1.0}


def _one(component: Component) -> hs.System:
    s = hs.System(component.name)
    s.add(component)
    return s


def test_a_state_that_overflows_is_refused_by_rk4() -> None:
    """x = 1/(1 - t) overflows near t = 1: the step is refused with the state's name, the time stays."""
    stepper = CStepper(_one(Blowup("blowup")), step=0.01, method="rk4")
    with pytest.raises(SolverError, match=r"the state blowup\.x became inf"):
        stepper.run(2.0)
    stuck = stepper.time
    assert 0.9 < stuck < 1.1 and np.isfinite(stepper.state("blowup.x"))
    with pytest.raises(SolverError, match="became inf"):
        stepper.step()
    assert stepper.time == stuck


def test_an_implicit_step_without_solution_is_refused_by_bdf2() -> None:
    """Implicit Euler on dx/dt = x^2 from 1 with h = 0.3: z - 0.3 z^2 = 1 has no real root, so Newton cannot
    converge; the step is refused (status 1 or, if an iterate makes I - gamma J singular, 3), never passed over."""
    stepper = CStepper(_one(Blowup("blowup")), step=0.3, method="bdf2")
    with pytest.raises(SolverError, match=r"t = 0\.3 s: (Newton's iterations did not converge|the Newton matrix)"):
        stepper.step()
    assert stepper.time == 0.0 and stepper.state("blowup.x") == 1.0 and stepper.status in (1, 3)


def test_an_unsolved_algebraic_unknown_is_refused() -> None:
    """As every run of the engine checks it: with c = 1 the unknown has no root; with c = -1 it has."""
    stepper = CStepper(_one(Hopeless("hopeless")), step=1e-3, method="rk4")
    with pytest.raises(SolverError, match=r"algebraic unknown hopeless\.z was not solved"):
        stepper.step()
    stepper.set_parameter("hopeless.c", -1.0)
    stepper.reset()
    t, values = stepper.run(0.01)
    z = np.sqrt(1.0 - values[:, 0] ** 2)  # dx/dt = -sqrt(1 - x^2): x = sin(asin(0.5) - t)
    np.testing.assert_allclose(values[:, stepper.signals.index("hopeless.z")], z, rtol=1e-9)
    np.testing.assert_allclose(values[:, 0], np.sin(np.arcsin(0.5) - t), rtol=1e-9)


# -- the C API without Python ----------------------------------------------------------------------
MAIN = r"""
#include <stdio.h>
#include "spring.h"
#include "blowup.h"

int main(void) {
    spring_instance *s = spring_new();
    static double memory[4096];
    blowup_instance *b = blowup_init(memory);
    if (blowup_instance_size() > sizeof memory) return 3;
    spring_set_parameter(s, spring_find(spring_parameter_names, "load.k_spring"), 1250.0);
    spring_reset(s);
    for (int i = 0; i < 500; ++i) {
        if (spring_step(s) != SPRING_OK) return 1;
    }
    printf("%.17g %.17g\n", spring_time(s), spring_get_state(s, spring_find(spring_state_names, "load.x")));
    int status = 0;
    while (status == BLOWUP_OK) status = blowup_step(b);
    printf("%d %.17g %s\n", status, blowup_time(b), blowup_message(b));
    spring_free(s);
    return 0;
}
"""


def test_two_models_in_one_c_program(tmp_path: Any) -> None:
    """Two exported models link into one program (every symbol prefixed) that runs with no Python: its
    numbers are the Python-loaded stepper's, to the last digit."""
    spring, blowup = _driven_spring(), _one(Blowup("blowup"))
    first = export_c(spring, tmp_path / "spring", step=0.002, method="bdf2", name="spring")
    second = export_c(blowup, tmp_path / "blowup", step=0.01, method="rk4")
    assert second.name == "blowup"
    (tmp_path / "main.c").write_text(MAIN)
    sources = [str(p) for p in (*first.sources, *second.sources)]
    command = [*compiler(), "-O2", "-Ispring", "-Iblowup", "-o", "main", "main.c", *sources, "-lm"]
    subprocess.run(command, cwd=tmp_path, check=True)
    printed = subprocess.run([str(tmp_path / "main")], capture_output=True, text=True, check=True).stdout.splitlines()
    stepper = CStepper(spring, step=0.002, method="bdf2")
    stepper.set_parameter("load.k_spring", 1250.0)
    stepper.reset()
    stepper.advance(500)
    assert [float(v) for v in printed[0].split()] == [stepper.time, stepper.state("load.x")]
    assert printed[1].startswith("2 ") and "blowup.x became inf" in printed[1]


def test_readme_example_compiles_and_runs(tmp_path: Any) -> None:
    export = export_c(_driven_spring(), tmp_path, step=0.001, method="rk4")
    readme = (tmp_path / "README.md").read_text()
    code = re.search(r"```c\n(.*?)```", readme, re.S)
    assert code is not None
    (tmp_path / "example.c").write_text(code.group(1))
    sources = [p.name for p in export.sources]
    subprocess.run([*compiler(), "-std=c99", "-Wall", "-Werror", "-o", "example", "example.c", *sources, "-lm"],
                   cwd=tmp_path, check=True)  # fmt: skip
    out = subprocess.run([str(tmp_path / "example")], capture_output=True, text=True, check=True).stdout
    assert out.startswith("t = 1 s: load.x = ") and out.strip().endswith(" m")
    assert "| `load.k_spring` | 800.0 | `N/m` |" in readme


# -- bad input ----------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"step": 0.0}, r"step '0\.0': expected a positive, finite step"),
        ({"step": "1 bar"}, "wrong dimension"),
        ({"step": 1e-3, "method": "euler"}, "method 'euler': expected one of rk4, bdf2"),
        ({"step": 1e-3, "inputs": ["load.push"]}, "'load' has no input 'push'; expected one of load.F, load.F_P1, load.F_ext"),
        ({"step": 1e-3, "inputs": ["lever.u"]}, "no component 'lever'"),
        ({"step": 1e-3, "inputs": ["load.F_ext", "load.F_ext"]}, "given twice"),
        ({"step": 1e-3, "name": "double"}, "expected a C identifier"),
    ],
)
def test_bad_arguments_write_nothing(tmp_path: Any, kwargs: dict[str, Any], message: str) -> None:
    with pytest.raises(HydroservoError, match=message):
        export_c(_driven_spring(), tmp_path / "out", **kwargs)
    assert list(tmp_path.iterdir()) == []


def test_existing_files_are_kept_unless_forced(tmp_path: Any) -> None:
    export_c(_driven_spring(), tmp_path, step=1e-3)
    (tmp_path / "driven_spring.c").write_text("mine")
    with pytest.raises(ParameterError, match="already exist"):
        export_c(_driven_spring(), tmp_path, step=1e-3)
    assert (tmp_path / "driven_spring.c").read_text() == "mine"
    export_c(_driven_spring(), tmp_path, step=1e-3, force=True)
    assert "driven_spring_step" in (tmp_path / "driven_spring.c").read_text()


def test_a_system_without_states_has_nothing_to_step(tmp_path: Any) -> None:
    with pytest.raises(ModelError, match="no states"):
        export_c(_one(c.Sine("sine")), tmp_path, step=1e-3)


def test_c_identifier() -> None:
    assert [c_identifier(n) for n in ("servo-solenoid-cylinder", "a--b", "2nd", "", "static")] == [
        "servo_solenoid_cylinder", "a_b", "m_2nd", "model", "static_model"]  # fmt: skip


# -- slow: the method's limits on the built-in models ---------------------------------------------------
@pytest.mark.slow
def test_rk4_stability_limit_of_the_flight_simulator(flight_reference: hs.Result) -> None:
    """The first-stage torque motor (about 4580 rad/s at damping 0.4) bounds rk4: stable at 0.5 ms (within
    1e-6 of range), its states overflowing at 0.64 ms (h |lambda| = 2.9), which the stepper refuses."""
    system = hs.load_model("flight-simulator")
    stable = CStepper(system, step=5e-4, method="rk4")
    t, values = stable.run(2.0)
    assert _deviation(stable, t, values, flight_reference, "y") < 1e-6
    with pytest.raises(SolverError, match="became (-?inf|-?nan)"):
        CStepper(system, step=6.4e-4, method="rk4").run(2.0 - 2.0 % 6.4e-4)


@pytest.mark.slow
def test_bdf2_long_steps_on_the_flight_simulator(flight_reference: hs.Result) -> None:
    """Eight times the rk4 limit: bdf2 at 5 ms stays within 1e-3 of range (measured 7.8e-4), at 1 ms within 5e-5."""
    system = hs.load_model("flight-simulator")
    for h, bound in ((1e-3, 5e-5), (5e-3, 1e-3)):
        stepper = CStepper(system, step=h, method="bdf2")
        t, values = stepper.run(2.0)
        index = stepper.signals.index("y")
        y = np.interp(flight_reference.t, t, values[:, index])
        assert np.max(np.abs(y - flight_reference["y"])) / np.ptp(flight_reference["y"]) < bound, h


@pytest.mark.slow
def test_bdf2_on_the_servo_solenoid_is_first_order_across_the_reference_step() -> None:
    """The two-step formula spans the reference's jump at 10 ms: one O(h) error, halving with the step
    (measured 4.2e-4 and 2.1e-4 of the position's range at 0.1 and 0.05 ms), never a refused step."""
    system = hs.load_model("servo-solenoid-cylinder")
    ref = _tight(system, 0.4, 1e-3)
    found = []
    for h in (1e-4, 5e-5):
        stepper = CStepper(system, step=h, method="bdf2")
        t, values = stepper.run(0.4)
        found.append(_deviation(stepper, t, values, ref, "x_mm"))
    assert found[0] < 1e-3 and found[0] / found[1] == pytest.approx(2.0, rel=0.1)

# -- the variable-step solvers of every export (integrate: dopri5 and ros23) ---------------------------
# The variable-step solvers of every C export (``integrate``: dopri5 and ros23): their order, their error
# control, their dense output, their agreement with CVODES and their refusals.
#
# The order is observed on the driven spring of ``test_c`` (a closed-form solution): with steps of at most h and
# tolerances too loose to bind, every step but the first few is h long, so the error at the end falls as h^p for
# a method of order p. Deviations from CVODES are relative to the range of each
# signal over the run, CVODES at rtol 1e-10 (about 1e-9 of range).


@pytest.fixture(scope="module")
def spring() -> CStepper:
    """The driven spring's export, loaded."""
    return CStepper(_driven_spring(), step=1e-3)


def _end_error(stepper: CStepper, method: str, h: float = 0.0, rtol: float = 0.5, atol: float = 1.0) -> float:
    stepper.reset()
    states, _ = stepper.integrate([0.0, 1.0], method=method, rtol=rtol, atol=atol, max_step=h)
    return abs(states[-1, stepper.export.states.index("load.x")] - _driven_spring_position(np.array([1.0]))[0])


@pytest.mark.parametrize(("method", "order"), [("dopri5", 5), ("ros23", 2), ("rodas3", 3)])
def test_observed_order_of_the_variable_step_methods(spring: CStepper, method: str, order: int) -> None:
    """Halving the step divides the error by 2^p, within half an order (a wrong coefficient loses one or more)."""
    coarse, fine = _end_error(spring, method, 0.02), _end_error(spring, method, 0.01)
    observed = np.log2(coarse / fine)
    assert order - 0.5 < observed < order + 0.7, (coarse, fine, observed)


@pytest.mark.parametrize("method", ["dopri5", "ros23", "rodas3"])
def test_error_control_follows_the_tolerance(spring: CStepper, method: str) -> None:
    """The tolerance sets the steps: the error at 1 s (of a 10 mm swing) stays within 1000 rtol of the amplitude
    (a local tolerance: the global error of three undamped periods adds up over the steps, most for the
    second-order ros23, 670 rtol at rtol 1e-7), and shrinks by at least 10x for a 1000x tighter tolerance."""
    errors = [_end_error(spring, method, rtol=rtol, atol=rtol / 100) for rtol in (1e-4, 1e-7)]
    assert errors[0] < 1000 * 1e-4 * 0.01 and errors[1] < 1000 * 1e-7 * 0.01
    assert errors[1] < errors[0] / 10


@pytest.mark.parametrize("method", ["dopri5", "ros23", "rodas3"])
def test_every_output_time_ends_a_step(spring: CStepper, method: str) -> None:
    """No step passes an output time, so outputs are the steps' own ends (not interpolated) and an input cannot
    change between two of them unseen: within 1000 rtol of the swing of the closed form (the bound of the
    steps' own global error, above) at every one of 2001 times, in at least 2000 steps; and a step shortened to
    land on an output time does not slow the steps after it (few more steps than outputs)."""
    spring.reset()
    times = np.linspace(0.0, 1.0, 2001)
    states, _ = spring.integrate(times, method=method, rtol=1e-6, atol=1e-8)
    x = states[:, spring.export.states.index("load.x")]
    assert np.max(np.abs(x - _driven_spring_position(times))) < 1000 * 1e-6 * 0.01
    stats = spring.integration_statistics()
    assert 2000 <= stats["steps"] < 2300 and stats["rejected"] < stats["steps"]


@pytest.fixture(scope="module")
def flight() -> tuple[CStepper, hs.Result]:
    """The flight simulator's export, and CVODES at rtol 1e-10 on 401 times."""
    system = hs.load_model("flight-simulator")
    grid = np.linspace(0.0, 2.0, 401)
    return CStepper(system, step=1e-4), system.simulate(t_eval=grid, rtol=1e-10, atol=1e-12, method="cvodes")


@pytest.mark.parametrize("method", ["dopri5", "ros23", "rodas3"])
def test_flight_simulator_agrees_with_cvodes(flight: tuple[CStepper, hs.Result], method: str) -> None:
    """At rtol 1e-5 (accuracy 1e-3) the states and the main outputs are within 1e-3 of their range of CVODES'."""
    stepper, ref = flight
    stepper.reset()
    states, outputs = stepper.integrate(ref.t, method=method, rtol=1e-5, atol=1e-7)
    for name in ("y", "p1", "p2", "xv"):
        if name in stepper.export.states:
            column = states[:, stepper.export.states.index(name)]
        else:
            column = outputs[:, stepper.export.outputs.index(name)]
        assert np.max(np.abs(column - ref[name])) <= 1e-3 * np.ptp(ref[name]), name


def test_refusals_name_the_reason(flight: tuple[CStepper, hs.Result]) -> None:
    stepper, _ = flight
    stepper.reset()
    with pytest.raises(ParameterError, match="expected one of dopri5, ros23"):
        stepper.integrate([0.0, 1.0], method="euler")
    with pytest.raises(SolverError, match="not after the one before"):
        stepper.integrate([0.0, 1.0, 1.0], method="ros23")
    with pytest.raises(SolverError, match="step budget of 10 steps was used up"):
        stepper.integrate([0.0, 2.0], method="dopri5", max_steps=10)
    assert 0.0 < stepper.time < 2.0  # left at the last accepted step


def test_the_readmes_tables_keep_a_description_with_line_breaks_and_bars_in_its_cell() -> None:
    from hydroservo.codegen.c import _markdown_table

    table = _markdown_table(("name", "description"), [("`y`", "first line\n| not a row | x\r\u2028end")])
    lines = table.splitlines()
    assert len(lines) == 3 and lines[2].count(" | ") == 1 and "\\n" in lines[2] and "\\|" in lines[2]
