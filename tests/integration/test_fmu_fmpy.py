"""FMUs of the built-in models, built here and run in FMPy (the FMI reference importer), against the engine.

Each FMU is built once per module (about 1 s of C compiling each); the module is skipped without a C
compiler or FMPy. Deviations are relative to the engine signal's range over the run,
max |FMU - engine| / (max - min), on the engine's output times (FMPy is asked for the same grid).

Tolerances, and why:
* Model Exchange against the engine, both at their defaults (the engine: accuracy 1e-4 of range, CVODES
  rtol 1e-6 / atol 1e-8 of nominal; FMPy: CVODE at the FMU's default tolerance 1e-6 with atol 1e-6 of
  nominal): 1e-3 of range on the model's main signals. Measured: flight-simulator 4.5e-5,
  servo-solenoid 1.5e-4, robot-arm 2.7e-4. The two integrators' own errors, not the model, set it.
* Model Exchange against the engine, both tight (engine accuracy 1e-6, FMPy rtol 1e-9): 1e-4 on every
  state of the flight-simulator (measured 1.8e-5 on the torque-motor velocity, 8e-7 on the pressures).
  This is the test that the FMU holds the same equations.
* Co-Simulation (rk4 at 0.1 ms inside) against the engine: 1e-3 of range on the main signals
  (measured 4e-5 flight-simulator, 2e-5 servo-solenoid; robot-arm 4.5e-3 on cyl.pA, compared at 1e-2:
  the Stribeck friction near zero speed is the fixed step's hardest part).
"""

from __future__ import annotations

import ctypes
import subprocess
import warnings
import zipfile
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.codegen.c import CStepper, compiler
from hydroservo.codegen.fmu import FmuExport, export_fmu
from hydroservo.errors import ImplausibleResultWarning, ParameterError
from hydroservo.system.assembly import assemble
from hydroservo.system.model import Model

fmpy = pytest.importorskip("fmpy")
from fmpy import extract, read_model_description, simulate_fmu  # noqa: E402
from fmpy.fmi1 import FMICallException  # noqa: E402
from fmpy.fmi2 import (  # noqa: E402
    FMU2Model,
    FMU2Slave,
    defaultCallbacks,  # noqa: E402
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
)
from fmpy.validation import validate_fmu  # noqa: E402

try:
    compiler()
except ParameterError:
    pytest.skip("no C compiler", allow_module_level=True)


@pytest.fixture(scope="module")
def flight(tmp_path_factory: pytest.TempPathFactory) -> tuple[hs.System, FmuExport]:
    system = hs.load_model("flight-simulator")
    return system, export_fmu(system, tmp_path_factory.mktemp("flight"), inputs=["summer.u1"])


@pytest.fixture(scope="module")
def solenoid(tmp_path_factory: pytest.TempPathFactory) -> tuple[hs.System, FmuExport]:
    system = hs.load_model("servo-solenoid-cylinder")
    return system, export_fmu(system, tmp_path_factory.mktemp("solenoid"))


def _main_signals(system: hs.System) -> list[str]:
    return [name for panel in system.default_panels() for name in panel]


def _deviations(system: hs.System, export: FmuExport, fmi_type: str, signals: list[str], **engine: Any) -> dict[str, float]:
    """max |FMU - engine| / range of each signal (a constant signal: its largest difference), in FMPy."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ImplausibleResultWarning)
        ref = system.simulate(**engine)
    names = {v.signal: v.name for v in export.variables}
    t = np.asarray(ref.t)
    got = simulate_fmu(str(export.path), fmi_type=fmi_type, stop_time=float(t[-1]), output_interval=float(t[1] - t[0]),
                       output=[names[s] for s in signals])  # fmt: skip
    assert np.allclose(got["time"], t, rtol=0, atol=1e-9)
    found = {}
    for s in signals:
        difference = float(np.max(np.abs(got[names[s]] - np.asarray(ref[s]))))
        scale = float(np.ptp(ref[s]))
        found[s] = difference / scale if scale > 0 else difference
    return found


def test_fmpy_finds_no_problem_in_the_fmus(flight, solenoid) -> None:
    for _, export in (flight, solenoid):
        assert validate_fmu(str(export.path)) == []
        with zipfile.ZipFile(export.path) as archive:
            assert f"binaries/{export.platform}/{export.name}.so" in archive.namelist()


@pytest.mark.parametrize("fmi_type", ["ModelExchange", "CoSimulation"])
@pytest.mark.parametrize("which", ["flight", "solenoid"])
def test_fmu_agrees_with_the_engine(which: str, fmi_type: str, request: pytest.FixtureRequest) -> None:
    system, export = request.getfixturevalue(which)
    found = _deviations(system, export, fmi_type, _main_signals(system))
    assert max(found.values()) < 1e-3, found


def test_model_exchange_holds_the_engines_equations(flight) -> None:
    """Both integrators tight: every state within 1e-4 of its range (the module notes)."""
    system, export = flight
    ref = system.simulate(accuracy=1e-6)
    t = np.asarray(ref.t)
    got = simulate_fmu(str(export.path), fmi_type="ModelExchange", stop_time=float(t[-1]),
                       output_interval=float(t[1] - t[0]), relative_tolerance=1e-9, output=list(export.states))  # fmt: skip
    for name in export.states:
        assert np.max(np.abs(got[name] - ref[name])) < 1e-4 * np.ptp(ref[name]), name


def test_parameters_and_inputs_act_as_in_the_engine(flight) -> None:
    """A start value set through FMPy is the engine's parameter; the input summer.u1 adds to the command,
    so a constant 0.2 V on it is the engine's source offset raised by 0.2 V."""
    system, export = flight
    offset = system.parameter_vector()[list(export.parameters).index("source.offset")]
    heavy = {"load.W": 3000 * 4.4482216152605, "load.B": 5000.0}
    ref = system.simulate(params={**heavy, "source.offset": offset + 0.2})
    t = np.asarray(ref.t)
    signal = np.array([(0.0, 0.2), (float(t[-1]), 0.2)], dtype=[("time", float), ("summer.u1", float)])
    for fmi_type in ("ModelExchange", "CoSimulation"):
        got = simulate_fmu(str(export.path), fmi_type=fmi_type, stop_time=float(t[-1]),
                           output_interval=float(t[1] - t[0]), start_values=heavy, input=signal, output=["y", "p1"])  # fmt: skip
        for name in ("y", "p1"):
            assert np.max(np.abs(got[name] - ref[name])) < 1e-3 * np.ptp(ref[name]), (fmi_type, name)
    plain = system.simulate()
    assert np.max(np.abs(plain["y"] - ref["y"])) > 0.1 * np.ptp(ref["y"])  # the changes matter


class _Log:
    """FMI callbacks that keep the FMU's messages."""

    def __init__(self) -> None:
        self.messages: list[str] = []
        self.logger = fmi2CallbackLoggerTYPE(self._log)
        self.callbacks = fmi2CallbackFunctions()
        self.callbacks.logger = self.logger
        self.callbacks.allocateMemory = defaultCallbacks.allocateMemory
        self.callbacks.freeMemory = defaultCallbacks.freeMemory

    def _log(self, env: Any, name: Any, status: int, category: bytes, message: bytes) -> None:
        self.messages.append(message.decode().replace("%%", "%"))


def _instance(export: FmuExport, kind: type, log: _Log, *, initialised: bool = False) -> Any:
    """An instance of the FMU (FMU2Model or FMU2Slave) logging into ``log``; initialised at t = 0 if asked."""
    unzipped = extract(str(export.path))
    description = read_model_description(unzipped)
    fmu = kind(guid=description.guid, unzipDirectory=unzipped, modelIdentifier=export.name, instanceName="test")
    fmu.instantiate(callbacks=log.callbacks)
    if initialised:
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
    return fmu


def test_co_simulation_refuses_what_it_cannot_do(flight) -> None:
    """A fixed parameter after the initialisation, a value out of range, a step that is not a whole number of
    the stepper's, a start other than 0: each refused with a message naming it; the FMU goes on afterwards."""
    _, export = flight
    log = _Log()
    fmu = _instance(export, FMU2Slave, log)
    with pytest.raises(FMICallException):
        fmu.setupExperiment(startTime=1.0)
    assert "startTime = 1 s" in log.messages[-1]
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    mass = export.value_reference("load.m")
    with pytest.raises(FMICallException):
        fmu.setReal([mass], [-5.0])
    assert log.messages[-1].startswith("fmi2SetReal: load.m = -5 kg: expected a finite value in (0")
    fmu.exitInitializationMode()
    with pytest.raises(FMICallException):
        fmu.setReal([export.value_reference("load.x0")], [0.1])
    assert "load.x0 is a fixed parameter" in log.messages[-1]
    with pytest.raises(FMICallException):
        fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1.5e-4)
    assert "whole number of the FMU's fixed steps of 0.0001 s" in log.messages[-1]
    fmu.setReal([mass], [500.0])  # tunable: accepted between steps
    fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1e-3)
    assert fmu.getReal([mass]) == [500.0]
    with pytest.raises(FMICallException):
        fmu.doStep(currentCommunicationPoint=0.5, communicationStepSize=1e-3)
    assert "expected the FMU's time, 0.001 s" in log.messages[-1]
    # A host's time that drifted by rounding (t += H over a long run) is taken as the FMU's within half a step,
    # the step to a thousandth of a step:
    fmu.doStep(currentCommunicationPoint=1e-3 + 4e-5, communicationStepSize=1e-3 - 5e-8)
    assert fmu.getRealStatus(2) == pytest.approx(2e-3, abs=1e-15)  # fmi2LastSuccessfulTime: whole steps
    with pytest.raises(FMICallException):
        fmu.doStep(currentCommunicationPoint=2e-3 + 6e-5, communicationStepSize=1e-3)
    with pytest.raises(FMICallException):
        fmu.doStep(currentCommunicationPoint=float("nan"), communicationStepSize=1e-3)
    fmu.terminate()
    fmu.freeInstance()


def _pointer(array: np.ndarray) -> Any:
    return array.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


def test_model_exchange_gives_the_models_own_functions(flight) -> None:
    """The initial states, the rates and the nominal magnitudes are the engine's own, to rounding."""
    system, export = flight
    log = _Log()
    fmu = _instance(export, FMU2Model, log, initialised=True)
    n = len(export.states)
    x, rates, nominal = np.zeros(n), np.zeros(n), np.zeros(n)
    fmu.getContinuousStates(_pointer(x), n)
    model = system.build()
    p = np.append(system.parameter_vector(), 0.0)  # the input summer.u1 at 0
    assert np.allclose(x, np.asarray(model.x0(p[:-1])).ravel(), rtol=1e-12, atol=0)
    fmu.enterContinuousTimeMode()
    fmu.setTime(0.25)
    x = x * 1.01 + 1e-3 * np.asarray(model.nominal)
    fmu.setContinuousStates(_pointer(x), n)
    fmu.getDerivatives(_pointer(rates), n)
    expected = np.asarray(model.f(0.25, x, p[:-1])).ravel()
    assert np.allclose(rates, expected, rtol=1e-10, atol=1e-12 * np.max(np.abs(expected)))
    fmu.getNominalsOfContinuousStates(_pointer(nominal), n)
    assert np.array_equal(nominal, model.nominal)
    fmu.terminate()
    fmu.freeInstance()


def test_directional_derivatives_are_the_models_jacobian(flight) -> None:
    """fmi2GetDirectionalDerivative along every state and the input, for every state derivative and output:
    the engine model's exact Jacobian (its full matrix, built here) times the direction, to rounding."""
    import casadi as ca

    system, export = flight
    log = _Log()
    fmu = _instance(export, FMU2Model, log, initialised=True)
    n = len(export.states)
    x = np.zeros(n)
    fmu.getContinuousStates(_pointer(x), n)
    model = system.build()
    x = x * 1.01 + 1e-3 * np.asarray(model.nominal)  # away from rest, where every term acts
    fmu.enterContinuousTimeMode()
    fmu.setTime(0.25)
    fmu.setContinuousStates(_pointer(x), n)
    fmu.setReal([export.value_reference("summer.u1")], [0.3])
    direction = np.linspace(1.0, 2.0, n + 1) * np.append(model.nominal, 1.0)  # each in its state's scale
    knowns = [export.value_reference(s) for s in export.states] + [export.value_reference("summer.u1")]
    derivatives = [export.value_reference(f"der({s})") for s in export.states]
    outputs = [export.value_reference(o) for o in export.outputs]
    got = np.array(fmu.getDirectionalDerivative(derivatives + outputs, knowns, list(direction)))
    perturbed = Model(assemble(system, perturbed=("summer.u1",)))  # the engine's model with the input
    t, xs, u = ca.SX.sym("t"), ca.SX.sym("x", n), ca.SX.sym("u")
    ps = ca.vertcat(system.parameter_vector(), u)
    rhs = ca.vertcat(perturbed.f(t, xs, ps), perturbed.outputs(t, xs, ps))
    jac = ca.Function("J", [t, xs, u], [ca.jacobian(rhs, ca.vertcat(xs, u))])  # reverse/forward: CasADi's choice
    expected = np.asarray(jac(0.25, x, 0.3)) @ direction
    names = [*export.outputs]
    assert len(got) == n + len(names)
    scale = np.maximum(np.abs(expected), 1e-12 * np.max(np.abs(expected)))
    assert np.max(np.abs(got - expected) / scale) < 1e-9
    state = fmu.getDirectionalDerivative([knowns[0]], knowns, list(direction))
    assert state == [direction[0]]  # a state, as an output, is its own direction
    fmu.terminate()
    fmu.freeInstance()


def test_the_sources_build_with_nothing_but_a_c_compiler(tmp_path: Path, solenoid) -> None:
    """A sources-only FMU, compiled as its documentation says, runs as the one built here."""
    system, built = solenoid
    export = export_fmu(system, tmp_path, binary=False)
    folder = tmp_path / "unzipped"
    with zipfile.ZipFile(export.path) as archive:
        archive.extractall(folder)
    binaries = folder / "binaries" / "linux64"
    binaries.mkdir(parents=True)
    sources = sorted(str(p) for p in (folder / "sources").glob("*.c"))
    subprocess.run([*compiler(), "-O2", "-shared", "-fPIC", "-o", str(binaries / f"{export.name}.so"), *sources, "-lm"],
                   check=True)  # fmt: skip
    a = simulate_fmu(str(folder), stop_time=0.1, output=["xs"])
    b = simulate_fmu(str(built.path), stop_time=0.1, output=["xs"])
    assert np.array_equal(a["xs"], b["xs"])


@pytest.mark.parametrize("name", ["robot-arm", "position-servo"])
def test_the_other_built_in_models_validate_and_run(name: str, tmp_path: Path) -> None:
    """robot-arm within 1e-3 (Model Exchange) and 1e-2 (Co-Simulation) on its main signals; position-servo,
    whose relief valve limit-cycles (the engine itself is 2-4x off its accuracy there, docs/engine.md),
    on the load position alone: 1e-2 (measured 3e-4 and 2e-3)."""
    system = hs.load_model(name)
    export = export_fmu(system, tmp_path)
    assert validate_fmu(str(export.path)) == []
    signals = _main_signals(system) if name == "robot-arm" else ["load.x"]
    for fmi_type, bound in (("ModelExchange", 1e-3 if name == "robot-arm" else 1e-2), ("CoSimulation", 1e-2)):
        found = _deviations(system, export, fmi_type, signals)
        assert max(found.values()) < bound, (fmi_type, found)


def test_a_stepper_built_for_an_fmu_is_the_c_steppers(solenoid) -> None:
    """Co-Simulation runs the C stepper: the same numbers as CStepper at the same step and method."""
    system, export = solenoid
    t, values = CStepper(system, step=export.step, method=export.method).run(0.05)
    got = simulate_fmu(str(export.path), fmi_type="CoSimulation", stop_time=0.05, output_interval=export.step,
                       output=["xs", "cyl.pA"])  # fmt: skip
    for name in ("xs", "cyl.pA"):
        column = values[:, [*export.states, *export.outputs].index(name)]
        assert np.allclose(got["time"], t, rtol=0, atol=1e-12)
        assert np.allclose(got[name], column, rtol=1e-12, atol=0), name


def test_an_fmu_state_goes_back_and_is_serialised(flight) -> None:
    """Co-Simulation: a state taken at 0.1 s, restored after 0.1 s more, gives the same run again, bit for bit;
    so does the same state serialised to bytes and read back; bytes of another size are refused."""
    _, export = flight
    log = _Log()
    fmu = _instance(export, FMU2Slave, log, initialised=True)
    y, h = [export.value_reference("y"), export.value_reference("p1")], 1e-3

    def run(t0: float, steps: int) -> list[list[float]]:
        found = []
        for k in range(steps):
            fmu.doStep(currentCommunicationPoint=t0 + k * h, communicationStepSize=h)
            found.append(fmu.getReal(y))
        return found

    run(0.0, 100)
    state = fmu.getFMUstate()
    first = run(0.1, 100)
    fmu.setFMUstate(state)
    assert run(0.1, 100) == first
    data = fmu.serializeFMUstate(state)
    fmu.freeFMUstate(state)
    again = fmu.deSerializeFMUstate(data)
    fmu.setFMUstate(again)
    assert run(0.1, 100) == first
    with pytest.raises(FMICallException):
        fmu.deSerializeFMUstate(data[:-8])
    assert "expected" in log.messages[-1] and "a state of this FMU" in log.messages[-1]
    fmu.freeFMUstate(again)
    fmu.terminate()
    fmu.freeInstance()


@pytest.mark.parametrize("method", ["rodas3", "ros23", "dopri5"])
def test_co_simulation_with_a_variable_step_method(method: str, tmp_path: Path) -> None:
    """--method rodas3/ros23/dopri5: Co-Simulation with error control over any communication step (here 7 ms and 3 ms,
    not multiples of anything), within 1e-3 of range of the engine on the flight simulator's main signals at
    accuracy 1e-4; an unknown method is refused."""
    system = hs.load_model("flight-simulator")
    export = export_fmu(system, tmp_path, method=method, accuracy=1e-4)
    assert validate_fmu(str(export.path)) == []
    signals = _main_signals(system)
    for interval in (7e-3, 3e-3):
        got = simulate_fmu(str(export.path), fmi_type="CoSimulation", stop_time=1.4, output_interval=interval,
                           output=signals)  # fmt: skip
        ref = system.simulate(t_eval=got["time"], rtol=1e-10, atol=1e-12, method="cvodes")
        for name in signals:
            assert np.max(np.abs(got[name] - ref[name])) <= 1e-3 * np.ptp(ref[name]), (interval, name)
    with pytest.raises(ParameterError, match="expected one of rk4, bdf2, dopri5, ros23"):
        export_fmu(system, tmp_path, method="euler")
