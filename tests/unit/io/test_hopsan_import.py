"""Hopsan models imported (hydroservo.io.hopsan_library, ``hydroservo import-hopsan``).

The model file of Hopsan's example "Position Servo" is written here from its components, parameters and
connections (as Hopsan's repository holds it, Models/Example Models/Position Servo.hmf; the values that do not
bear on the run, such as temperatures and wave variables, left out), so that no file of Hopsan's is shipped. The
imported model is compared with Hopsan's own converged result (hydroservo/data/reference/, with how it was made).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hydroservo.data import reference_text
from hydroservo.errors import ImplausibleResultWarning, ModelFileError
from hydroservo.io.hopsan_library import LIBRARY, REFUSED, import_hopsan, read_hopsan, safe_name

COMPONENTS = [
    ('HydraulicTankC', 'Tank_C', {'p': ('100000', 'Pa')}),
    ('MechanicTranslationalMass', 'Mass', {'m': ('100', 'kg'), 'B#Value': ('0', 'Ns/m'), 'k#Value': ('0', 'N/m'), 'x_min#Value': ('0', 'm'), 'x_max#Value': ('1', 'm')}),
    ('MechanicPositionSensor', 'Position_Sensor', {'P1#Position': ('0', 'm')}),
    ('HydraulicVolumeMultiPort', 'Hydraulic_Volume_Multi_Port', {'P1#Pressure': ('100000', 'Pa'), 'P_high': ('2e+007', 'Pa'), 'V#Value': ('0.001', 'm^3'), 'Beta_e#Value': ('1e+009', 'Pa'), 'alpha#Value': ('0.3', '-')}),
    ('SignalSink', 'Sink', {'in_bottom#Value': ('0', '')}),
    ('HydraulicTankC', 'Tank_C_1', {'p': ('100000', 'Pa')}),
    ('SignalGain', 'GainI', {'in#Value': ('0', ''), 'k#Value': ('0.000672426', '')}),
    ('HydraulicTankC', 'Tank_C_2', {'p': ('100000', 'Pa')}),
    ('SignalSubtract', 'Subtract', {'in1#Value': ('0', ''), 'in2#Value': ('0', '')}),
    ('SignalIntegrator2', 'Integrator', {'in#Value': ('0', ''), 'out#Value': ('0', '')}),
    ('HydraulicPressureReliefValve', 'Pressure_Relief_Valve', {'p_max#Value': ('2e+07', 'Pa'), 'tao#Value': ('0.001', 's'), 'p_h#Value': ('0', 'Pa'), 'k_cs': ('1e-008', '(m^3/s)/Pa'), 'k_cf': ('1e-008', '(m^3/s)/Pa'), 'q_nom': ('0.01', 'm^3/s')}),
    ('SignalStep', 'Step', {'y_0#Value': ('0.2', ''), 'y_A#Value': ('0.5', ''), 't_step#Value': ('1', 's')}),
    ('HydraulicFixedDisplacementPump', 'Q_type_Fixed_Displacement_Pump_1', {'a#Value': ('0', ''), 'n_p#Value': ('200', 'rad/s'), 'D_p#Value': ('25e-05', 'm^3/rev'), 'C_lp#Value': ('1e-12', '(m^3/s)/Pa')}),
    ('SignalGain', 'GainP', {'in#Value': ('0', ''), 'k#Value': ('0.0264249', '')}),
    ('MechanicFixedPosition', 'Fixed_Position_Attachment', {'m_e': ('1', 'kg')}),
    ('SignalAdd', 'Add', {'in1#Value': ('0', ''), 'in2#Value': ('0', '')}),
    ('MechanicTranslationalSpring', 'Translational_Spring', {'P1#Position': ('0', 'm'), 'P2#Position': ('0', 'm'), 'k#Value': ('100', 'N/m')}),
    ('Hydraulic43Valve', '4_3_Servo_Valve', {'xv#Value': ('0', ''), 'in#Value': ('0', 'm'), 'C_q#Value': ('0.67', '-'), 'rho#Value': ('890', 'kg/m^3'), 'd#Value': ('0.01', 'm'), 'f_pa#Value': ('1', '-'), 'f_pb#Value': ('1', '-'), 'f_at#Value': ('1', '-'), 'f_bt#Value': ('1', '-'), 'x_pa#Value': ('1e-4', 'm'), 'x_pb#Value': ('1e-4', 'm'), 'x_at#Value': ('1e-4', 'm'), 'x_bt#Value': ('1e-4', 'm'), 'x_vmax#Value': ('0.01', 'm'), 'omega_h': ('200', 'rad/s'), 'delta_h': ('1', '-')}),
    ('SignalSink', 'Scope', {'in_bottom#Value': ('0', '')}),
    ('HydraulicCylinderC', 'Cylinder_C', {'P1#Pressure': ('100000', 'Pa'), 'P2#Pressure': ('100000', 'Pa'), 'P3#Position': ('0', 'm'), 'A_1#Value': ('0.001', 'm^2'), 'A_2#Value': ('0.001', 'm^2'), 's_l#Value': ('1', 'm'), 'V_1#Value': ('0.0003', 'm^3'), 'V_2#Value': ('0.0003', 'm^3'), 'B_p#Value': ('0', 'Ns/m'), 'Beta_e#Value': ('1e+009', 'Pa'), 'c_leak#Value': ('0', '')}),
]
CONNECTIONS = [
    ('Mass.P1', 'Cylinder_C.P3'),
    ('4_3_Servo_Valve.PA', 'Cylinder_C.P1'),
    ('4_3_Servo_Valve.PB', 'Cylinder_C.P2'),
    ('Position_Sensor.P1', 'Mass.P2'),
    ('Position_Sensor.out', 'Subtract.in2'),
    ('Tank_C.P1', '4_3_Servo_Valve.PT'),
    ('Subtract.out', 'GainP.in'),
    ('Hydraulic_Volume_Multi_Port.P1', 'Pressure_Relief_Valve.P1'),
    ('Hydraulic_Volume_Multi_Port.P1', '4_3_Servo_Valve.PP'),
    ('Step.out', 'Subtract.in1'),
    ('Sink.in', '4_3_Servo_Valve.xv'),
    ('Tank_C_1.P1', 'Pressure_Relief_Valve.P2'),
    ('Integrator.out', 'GainI.in'),
    ('Add.out', '4_3_Servo_Valve.in'),
    ('Add.in1', 'GainP.out'),
    ('GainI.out', 'Add.in2'),
    ('Integrator.in', 'Subtract.out'),
    ('Pressure_Relief_Valve.xv', 'Sink.in_right'),
    ('Translational_Spring.P1', 'Mass.P2'),
    ('Fixed_Position_Attachment.Pm1', 'Translational_Spring.P2'),
    ('Position_Sensor.out', 'Scope.in'),
    ('Step.out', 'Scope.in'),
    ('Q_type_Fixed_Displacement_Pump_1.P1', 'Tank_C_2.P1'),
    ('Q_type_Fixed_Displacement_Pump_1.P2', 'Hydraulic_Volume_Multi_Port.P1'),
]


def _hmf(components: list, connections: list) -> str:
    objects = "".join(
        f'<component subtypename="" name="{name}" typename="{kind}" cqstype="S"><parameters>'
        + "".join(f'<parameter type="double" name="{k}" value="{v}" unit="{u}"/>' for k, (v, u) in params.items())
        + "</parameters></component>"
        for kind, name, params in components
    )
    links = "".join(
        f'<connect startcomponent="{a.rpartition(".")[0]}" startport="{a.rpartition(".")[2]}" '
        f'endcomponent="{b.rpartition(".")[0]}" endport="{b.rpartition(".")[2]}"/>'
        for a, b in connections
    )
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n<hopsanmodelfile hmfversion="0.4">'
        '<system subtypename="" name="Position Servo" typename="Subsystem">'
        '<simulationtime stop="3" timestep="0.0001" start="0" inherit_timestep="true"/>'
        f"<objects>{objects}</objects><connections>{links}</connections></system></hopsanmodelfile>"
    )


@pytest.fixture(scope="module")
def servo_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("hopsan") / "Position Servo.hmf"
    path.write_text(_hmf(COMPONENTS, CONNECTIONS), encoding="utf-8")
    return path


def _reference() -> np.ndarray:
    import io

    return np.genfromtxt(io.StringIO(reference_text("hopsan_position_servo.csv")), delimiter=",", names=True)


def test_position_servo_imported_matches_hopsans_converged_result(servo_file: Path) -> None:
    """Piston position and chamber-A pressure against Hopsan's converged traces (Richardson-extrapolated, uncertain
    to about 0.05 % of range): the issue's floor is 0.5 % of range; measured 0.0008 % and 0.01 %."""
    ref = _reference()
    system = read_hopsan(servo_file)
    with pytest.warns(Warning):  # the chamber peaks Hopsan's result has too (docs/hopsan.md)
        result = system.simulate(t_eval=ref["t_s"])
    x, xr = result.get("Mass.P2.Position"), ref["x_converged_m"]
    assert np.max(np.abs(x - xr)) < 0.005 * np.ptp(xr)
    p, pr = result.get("Cylinder_C.P1.Pressure"), ref["pA_converged_Pa"]  # absolute, as Hopsan logs it
    assert np.max(np.abs(p - pr)) < 0.005 * np.ptp(pr)
    # a sensor reads its node as Hopsan's does: the position sensor's output is the mass's P2 position
    assert np.allclose(result.get("Position_Sensor.out.Value"), x)
    # Hopsan's conventions: P1 of a mass counts outward the other way; a C port's force is the node's
    assert np.allclose(result.get("Mass.P1.Position"), -x)
    assert np.allclose(result.get("Cylinder_C.P3.Force"), result.get("Cylinder_C.F"))


def test_import_maps_every_component_and_keeps_hopsans_settings(servo_file: Path) -> None:
    imp = import_hopsan(servo_file)
    system = imp.system
    assert [path for path, _, _ in imp.mapping] == [name for _, name, _ in COMPONENTS]
    assert imp.names["4_3_Servo_Valve"] == "c_4_3_Servo_Valve"  # a name that starts with a digit
    assert system.t_end == 3.0 and system.meta["hopsan_timestep"] == "0.0001 s"
    assert "at a fixed step of 0.0001 s" in system.notes[0]
    assert imp.variables["Mass.P2.Position"] == "Mass#P2#Position"
    # values in Hopsan's units, absolute pressures as such
    assert system["Pressure_Relief_Valve"].given["p_crack"] == "20000000.0 Pa_abs"
    assert system["Cylinder_C"].values["V_B0"] == pytest.approx(3e-4 + 1e-3 * 1.0)
    # the sinks are dropped, and what they showed stays logged at its source
    assert "Sink" not in system.components and "Step.out.Value" in system.aliases


def test_imported_model_file_round_trips(servo_file: Path, tmp_path: Path) -> None:
    from hydroservo.io.model_file import load_model
    from hydroservo.workflows.hopsan import ImportHopsan

    report = ImportHopsan(servo_file).run()
    files = report.write(tmp_path / "out")
    text = Path(files["model"]).read_text(encoding="utf-8")
    assert "#   4_3_Servo_Valve (Hydraulic43Valve) -> a Gain" in text
    again = load_model(files["model"])
    t = np.linspace(0.0, 1.5, 301)
    with pytest.warns(Warning):
        a = report.imported.system.simulate(t_eval=t)
        b = again.simulate(t_eval=t)
    assert np.allclose(a.get("Mass.P2.Position"), b.get("Mass.P2.Position"), rtol=0, atol=1e-9)


def test_unsupported_components_are_listed_with_their_path(tmp_path: Path) -> None:
    components = [*COMPONENTS, ("HydraulicNoSuchType", "Plate", {}), ("SignalTimeDelay", "Wave", {})]
    path = tmp_path / "m.hmf"
    path.write_text(_hmf(components, CONNECTIONS), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"2 component\(s\).*Plate \(HydraulicNoSuchType\); Wave \(SignalTimeDelay: a pure time delay, y\(t\) = u\(t - deltat\), is no ordinary differential equation"):
        read_hopsan(path)


def test_unsupported_settings_are_refused_before_simulation(tmp_path: Path) -> None:
    components = [
        (k, n, {**p, "f_pa#Value": ("0.5", "-")} if k == "Hydraulic43Valve" else p) for k, n, p in COMPONENTS
    ]
    path = tmp_path / "m.hmf"
    path.write_text(_hmf(components, CONNECTIONS), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"4_3_Servo_Valve \(Hydraulic43Valve\): the edges' area fractions"):
        read_hopsan(path)


def test_safe_names() -> None:
    assert safe_name("4_3 Servo-Valve") == "c_4_3_Servo_Valve" and safe_name("Mass") == "Mass"
    assert "Hydraulic43Valve" in LIBRARY


def test_cli_writes_the_model_and_refuses_what_it_cannot_map(servo_file: Path, tmp_path: Path) -> None:
    run = [sys.executable, "-m", "hydroservo", "import-hopsan"]
    done = subprocess.run([*run, str(servo_file), "--out", str(tmp_path / "a"), "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    data = json.loads(done.stdout)
    assert Path(data["files"]["model"]).is_file() and len(data["components"]) == len(COMPONENTS)
    bad = tmp_path / "bad.hmf"
    bad.write_text(_hmf([*COMPONENTS, ("SignalTimeDelay", "Wave", {})], CONNECTIONS), encoding="utf-8")
    done = subprocess.run([*run, str(bad), "--out", str(tmp_path / "b")], capture_output=True, text=True)
    assert done.returncode == 2 and "Wave (SignalTimeDelay: a pure time delay" in done.stderr and "Traceback" not in done.stderr
    assert not (tmp_path / "b").exists()


def test_an_imported_model_linearises_runs_a_study_and_exports_an_fmu(tmp_path: Path) -> None:
    """Hopsan's Pressure Controlled Pump Simple, as imported (the shipped model file): a trim and its linear model
    (stable but for the velocity source's integrator), a one-at-a-time study of the control spring (a stiffer spring lets the pump regulate higher) and an
    FMU run by FMPy that agrees with the model's own run."""
    from hydroservo.analysis.linear import linearize
    from hydroservo.analysis.sensitivity import one_at_a_time
    from hydroservo.codegen.fmu import export_fmu
    from hydroservo.data import reference_path
    from hydroservo.io.model_file import load_model

    system = load_model(reference_path("hopsan/pressure-controlled-pump-simple.toml"))
    lin = linearize(
        system, "trim", t=2.0, inputs=["C_type_Pressure_Source_1.u"], outputs=["Hydraulic_Volume_Multi_Port.P1.Pressure"]
    )
    eig = np.linalg.eigvals(lin.A)
    still = np.abs(eig) < 1e-9  # the velocity source's position: an integrator of its (zero) velocity
    assert still.sum() == 1 and np.all(np.real(eig[~still]) < 0)
    study = one_at_a_time(
        system, {"Translational_Spring.k_spring": ["10000 N/m", "14000 N/m"]},
        metrics=["final(Hydraulic_Volume_Multi_Port.p)"], t_end=3.0,
    )
    finals = study.table["final(Hydraulic_Volume_Multi_Port.p) [Pa]"].to_numpy()
    assert finals[1] > finals[0] > 1e7
    fmpy = pytest.importorskip("fmpy")
    fmu = export_fmu(system, tmp_path / "fmu", method="rodas3")
    out = fmpy.simulate_fmu(str(fmu.path), stop_time=2.0, output=["Hydraulic_Volume_Multi_Port.p"], fmi_type="CoSimulation")
    own = system.simulate(t_eval=[0.0, 2.0])["Hydraulic_Volume_Multi_Port.p"][-1]
    assert out["Hydraulic_Volume_Multi_Port.p"][-1] == pytest.approx(own, rel=1e-3)


@pytest.mark.skipif(not os.environ.get("HOPSAN_SOURCE"), reason="needs HOPSAN_SOURCE, a clone of Hopsan's repository")
def test_shipped_imports_are_what_import_hopsan_writes_from_hopsans_files_today() -> None:
    """The model files beside the references (hydroservo/data/reference/hopsan/) are import-hopsan's output for
    the very files the references were made from (same SHA-256)."""
    import hashlib

    from hydroservo.data import reference_path, reference_text
    from hydroservo.validation.hopsan_examples import MODELS
    from hydroservo.workflows.hopsan import ImportHopsan

    index = json.loads(reference_text("hopsan/hopsan_examples.json"))
    source = Path(os.environ["HOPSAN_SOURCE"])
    for name, spec in MODELS.items():
        path = source / "Models" / spec.path
        assert hashlib.sha256(path.read_bytes()).hexdigest() == index[name]["sha256"], name
        assert ImportHopsan(path).run().text == reference_path(f"hopsan/{name}.toml").read_text(encoding="utf-8"), name


def test_a_sum_reads_each_signal_connected_to_its_one_port_and_time_starts_at_hopsans_start(tmp_path: Path) -> None:
    """Hopsan's SignalSum has one port 'in' that any number of signals join (three here); a model that starts
    at -1 s runs from 0 with its times shifted (the step at 0.5 s comes at 1.5 s)."""
    components = [
        ("SignalConstant", "A", {"y#Value": ("1.5", "")}),
        ("SignalConstant", "B", {"y#Value": ("2", "")}),
        ("SignalStep", "C", {"y_0#Value": ("0", ""), "y_A#Value": ("4", ""), "t_step#Value": ("0.5", "s")}),
        ("SignalSum", "Sum", {}),
        ("SignalSink", "Scope", {}),
    ]
    connections = [("A.y", "Sum.in"), ("B.y", "Sum.in"), ("C.out", "Sum.in"), ("Sum.out", "Scope.in")]
    text = _hmf(components, connections).replace('start="0"', 'start="-1"')
    path = tmp_path / "sum.hmf"
    path.write_text(text, encoding="utf-8")
    system = read_hopsan(path)
    r = system.simulate(t_eval=[0.0, 1.4, 1.6])
    assert list(r["Sum.out.Value"]) == pytest.approx([3.5, 3.5, 7.5])
    assert system.t_end == pytest.approx(4.0) and system.plots == [["Sum.out.Value"]]
    # more than three: further sums chained, each adding two inputs (six signals: two chained)
    more = [("SignalConstant", k, {"y#Value": (v, "")}) for k, v in (("D", "0.25"), ("E", "0.5"), ("F", "8"))]
    path.write_text(
        _hmf([*components, *more], [*connections, ("D.y", "Sum.in"), ("E.y", "Sum.in"), ("F.y", "Sum.in")]),
        encoding="utf-8",
    )
    system = read_hopsan(path)
    assert [n for n in system.components if n.startswith("Sum")] == ["Sum", "Sum_sum2", "Sum_sum3"]
    assert system.simulate(t_eval=[0.0, 1.0])["Sum.out.Value"][-1] == pytest.approx(1.5 + 2 + 4 + 0.25 + 0.5 + 8)


def test_parameters_set_by_constant_signals_take_their_values_and_others_are_refused(tmp_path: Path) -> None:
    """ServoOptimization sets its valve's diameter and stroke, its laps (through a gain of -1) and its piston's
    areas by constant signals: hydroservo holds the parameters at the signals' values. A parameter driven by a
    signal that varies (a step) is still refused."""
    components = [
        ("SignalConstant", "dv", {"y#Value": ("0.003", "")}),
        ("SignalConstant", "xol", {"y#Value": ("0.0001", "")}),
        ("SignalGain", "neg", {"k#Value": ("-1", ""), "in#Value": ("0", "")}),
        ("Hydraulic43Valve", "V", {"d#Value": ("0.01", "m"), "x_vmax#Value": ("0.01", "m"), "x_pa#Value": ("0", "m"),
                                   "x_pb#Value": ("0", "m"), "x_at#Value": ("0", "m"), "x_bt#Value": ("0", "m"),
                                   "C_q#Value": ("0.67", ""), "rho#Value": ("890", "kg/m^3")}),
        ("HydraulicPressureSourceC", "S", {"p#Value": ("1e7", "Pa")}),
        ("HydraulicTankC", "T", {}),
        ("HydraulicVolume", "VA", {}),
        ("HydraulicVolume", "VB", {}),
    ]
    connections = [("dv.y", "V.d"), ("dv.y", "V.x_vmax"), ("xol.y", "neg.in"), ("neg.out", "V.x_pa"),
                   ("neg.out", "V.x_bt"), ("S.P1", "V.PP"), ("T.P1", "V.PT"), ("VA.P1", "V.PA"), ("VB.P1", "V.PB")]
    path = tmp_path / "driven.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    system = read_hopsan(path)
    valve = system["V"]
    assert valve.values["c_v"] == pytest.approx(0.67 * np.pi * 0.003 * np.sqrt(2 / 890))
    assert valve.values["x_PA"] == pytest.approx(-1e-4) and valve.values["x_BT"] == pytest.approx(-1e-4)
    assert valve.values["x_PB"] == 0.0 and system["V_spool"].values["xv_max"] == pytest.approx(0.003)
    step = ("SignalStep", "st", {"y_0#Value": ("0.003", ""), "y_A#Value": ("0.001", ""), "t_step#Value": ("1", "s")})
    path.write_text(_hmf([*components, step], [*connections[1:], ("st.out", "V.d")]), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"V\.d driven by a signal is not supported yet"):
        read_hopsan(path)


CIRCUITS = Path(__file__).parent / "hopsan_circuits"
#: Circuits whose pressures the plausibility check flags, in Hopsan's runs as in hydroservo's: a flow source filling
#: a volume behind a relief valve set on its drop, which bounds no pressure of the circuit (relief2_valve_g: 26.7 MPa
#: in Hopsan's run), and a pump whose outlet the flow drawn closes against its orifice (pressure_controlled_pump_g:
#: 85.2 MPa in Hopsan's run)
_FLAGGED = {"relief2_valve_g": r"V\.p = ", "pressure_controlled_pump_g": r"Vol\.p = "}


def _simulate_flagged(system: Any, name: str, t: Any) -> Any:
    """The run of a circuit of :data:`_FLAGGED`, its flag expected (and checked), or of any other, unflagged."""
    if name not in _FLAGGED:
        return system.simulate(t_eval=t)
    with pytest.warns(ImplausibleResultWarning, match=_FLAGGED[name]):
        return system.simulate(t_eval=t)


@pytest.mark.parametrize(
    "name",
    ["spring_preload", "unequal_cylinder", "pump_at_zero", "start_value_order", "signal_blocks", "controllers",
     "shuttle_valve", "pressure_controlled_pump", "signal_blocks2", "mechanic_gears", "valve416", "orifices_g",
     "special_valves", "valve43", "valve63oc", "valve43ls", "relief2_valve_g",
     "motor_jload", "piston", "fuel_tank"],
)
def test_small_circuits_match_hopsan(name: str) -> None:
    """Each Hopsan variable these circuits log, against Hopsan's run (hopsan_circuits/README.md), within 0.5 % of
    its range (at least 1 % of its magnitude; forces, flows and signals from the second point, where Hopsan logs
    start values at t = 0: a controller's output its start value 0). The first four failed before their laws were
    imported: a spring's start force was dropped, an unequal-area cylinder's force lacked p_atm (A1 - A2), a
    displacement setting of 0 became 1, a sensor's start value overrode the spring's. The last two check signal
    blocks no model of Hopsan's repository uses (hysteresis, rounding, comparisons, logic) and the controllers
    SignalPIlead and SignalPID (clamped at their limits, with derivative input) closing loops through unit
    delays. The shuttle valve's (HydraulicShuttleValve) outlet follows the higher of a
    sine-wave pressure and a constant one, and drains back through the open inlet as the sine falls. The
    pressure-controlled pump (HydraulicPressureControlledPump) strokes at its rate limit, overshoots, destrokes to
    its lower bound and leaves it, and answers an orifice closed and a flow drawn (Hopsan's
    HydraulicPressureControlPumpVolumeTest.hmf, which its loader no longer reads, with a smaller draw). The
    second signal circuit checks the blocks no Hopsan example uses either: SignalMax, SignalMin and SignalSub over
    their multiports, SignalNot, SignalXor, SignalCounter (both edges, rising only), SignalSecondOrderFilter,
    SignalHP2Filter, Signal1DPLOLookupTable, Signal2DLookupTable, a numerical input into a slider and a display.
    The gears (MechanicRotationalInertiaWithSingleGear, driven through a shaft by a sine-wave speed against a
    torque, and a lossless MechanicBallScrew driving a spring by a sine-wave torque) have no model of Hopsan's.
    The 4/3 valve of four independent edges (HydraulicValve416, whose own test file Hopsan's loader no longer reads)
    fills and drains two volumes through edges of different widths and laps, their spool positions swept past
    Xvmax and below closing.
    The geometric orifices (HydraulicOrificeG, HydraulicOrificeCheckValveG, HydraulicSlitOrifice) pass a sine-wave
    pressure into drained volumes, laminar and turbulent, both ways (no Hopsan model uses them). The poppet valve
    (Hydraulic22PoppetValve) opens, rests at its stop, closes and rests on its seat as its supply rises and falls;
    the 3/3 shuttle valve (Hydraulic33ShuttleValve) shuttles between its stops under a sine-wave pressure at PP
    against a constant one at PT (no Hopsan model uses either). HydraulicValve43 (Special), driven past its stroke
    by a sine wave, with underlaps and a laminar onset of 1 bar, feeds two drained volumes (Hopsan's two models
    that use it, of core 0, its loader no longer reads); HydraulicValve63OC the same with overlaps and its open
    centre closing at 3 mm, and HydraulicValve43LS with its load-sensing port on a drained volume, whose flow
    Hopsan takes from none of A, B, T (no model of Hopsan's uses either). HydraulicPressureRelief2ValveG's spool
    with mass, underdamped, relieves a volume fed a sine-wave flow, striking both its stops. HydraulicMotorJload
    turns both ways under a sine-wave pressure against a sine-wave torque. HydraulicPiston pushes a mass against a
    spring, its rod-side chamber cavitating (its piston pulled by the chamber's pressure below 0 Pa absolute).
    HydraulicFuelTankG is drawn empty and refilled by a sine-wave flow, its mass held at its start value when
    filled beyond it."""
    imp = import_hopsan(CIRCUITS / f"{name}.hmf")
    text = (CIRCUITS / f"{name}.csv").read_text(encoding="utf-8")
    columns = text.splitlines()[0].split(",")
    ref = np.loadtxt(CIRCUITS / f"{name}.csv", delimiter=",", skiprows=1)
    result = _simulate_flagged(imp.system, name, ref[:, 0])
    by_hopsan = {hopsan: alias for alias, hopsan in imp.variables.items()}
    compared = 0
    for i, column in enumerate(columns[1:], start=1):
        if column not in by_hopsan:
            continue
        y, y_ref = result[by_hopsan[column]], ref[:, i]
        if column.endswith(("#Force", "#Flow", "#Value")):
            y, y_ref = y[1:], y_ref[1:]
        scale = max(float(np.ptp(y_ref)), 0.01 * float(np.max(np.abs(y_ref))), 1e-12)
        assert np.max(np.abs(y - y_ref)) <= 0.005 * scale, column
        compared += 1
    assert compared >= 8


#: Hopsan's logged variables of sources_sensors that are the Q sources' inputs in_p and in_f (0), not the node's
#: physics: no C component reads them (hopsan_library._q_source, _mechanic_q_source)
_LOGGED_INPUTS = ("QSource#P1#Pressure", "Volume#P2#Pressure", "MotionQ#P1#Force", "Spring#P2#Force")


def test_tlm_sources_and_node_sensors_match_hopsan() -> None:
    """HydraulicCSource (its wave variable a 10 bar level plus a sine, in_z = 0) feeding a volume through an
    orifice, emptied and filled by a HydraulicQSource's sine-wave flow; another (20 bar behind a sine-wave
    impedance in_z about 3e10 Pa s/m³) feeding a volume through an orifice and a leak; a MechanicTranslationalCSource (a sine
    force behind in_z = 50 N s/m) pushing a mass on a spring whose far end a MechanicTranslationalQSource moves (a
    sine velocity and its integral); node sensors on both. Every variable Hopsan logs agrees with its run
    (hopsan_circuits/sources_sensors.csv) within 0.5 % of its range, but the pressure and force of the Q sources'
    nodes: Hopsan logs their inputs in_p and in_f there (0 here), which no C component reads (its volume fills
    with in_q, its spring follows in_v), where hydroservo gives the volume's pressure and the spring's force."""
    imp = import_hopsan(CIRCUITS / "sources_sensors.hmf")
    kinds = {hopsan: became for hopsan, _, became in imp.mapping}
    assert kinds["CSource"] == "PressureSource CSource" and kinds["ForceC"] == "ForceSource ForceC"
    assert imp.system["CSourceZ"].option("impedance") == "input"
    assert kinds["MotionQ"] == "VelocitySource MotionQ"
    assert imp.system.connections["ForceC.B"] == "ForceC_B.y" and imp.system["ForceC_B"].values["value"] == 50.0
    columns = (CIRCUITS / "sources_sensors.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    ref = np.loadtxt(CIRCUITS / "sources_sensors.csv", delimiter=",", skiprows=1)
    result = imp.system.simulate(t_eval=ref[:, 0])
    by_hopsan = {hopsan: alias for alias, hopsan in imp.variables.items()}
    compared = 0
    for i, column in enumerate(columns[1:], start=1):
        if column in _LOGGED_INPUTS:
            assert np.all(ref[:, i] == 0.0), column  # Hopsan's in_p, in_f
            assert np.ptp(result[by_hopsan[column]]) > 1.0, column  # the volume's pressure, the spring's force
            continue
        if column not in by_hopsan:
            continue
        y, y_ref = result[by_hopsan[column]], ref[:, i]
        if column.endswith(("#Force", "#Flow", "#Value")):
            y, y_ref = y[1:], y_ref[1:]
        scale = max(float(np.ptp(y_ref)), 0.01 * float(np.max(np.abs(y_ref))), 1e-12)
        assert np.max(np.abs(y - y_ref)) <= 0.005 * scale, column
        compared += 1
    assert compared >= 30


def test_a_node_sensors_wave_variable_read_by_a_block_is_refused_with_why(tmp_path: Path) -> None:
    """HydraulicNodeSensor's c and Zc (and MechanicNodeSensor's out_c, out_z, out_em) belong to Hopsan's
    discretisation: shown in a scope they are dropped, read by a block the model is refused, saying why."""
    components = [("HydraulicTankC", "T", {}), ("HydraulicFlowSourceQ", "Q", {}), ("HydraulicNodeSensor", "S", {}),
                  ("SignalGain", "G", {}), ("SignalSink", "Scope", {})]
    connections = [("Q.P1", "T.P1"), ("S.P1", "T.P1"), ("S.Zc", "Scope.in"), ("S.p", "G.in")]
    path = tmp_path / "sensor.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    assert "S.p.Value" in import_hopsan(path).variables  # Zc on a scope: dropped
    path.write_text(_hmf(components, [*connections[:3], ("S.c", "G.in")]), encoding="utf-8")  # c into the gain
    with pytest.raises(ModelFileError, match=r"has no port 'c' that hydroservo maps .*: a quantity of Hopsan's "
                       r"discretisation"):
        read_hopsan(path)


#: the node of lossless_link where Hopsan's link meets its force source: Hopsan's logged velocity there carries
#: an undamped oscillation of its step
_LINK_NODE_VELOCITY = ("Force#P1#Velocity", "Link#P1#Velocity", "Link#P2#Velocity", "Stiff#P1#Velocity")


def test_mechanic_lossless_connector_matches_hopsan() -> None:
    """MechanicTranslationalLosslessConnector as a RigidLink, twice: between a sine force (a C source of no
    impedance) and a stiff spring on a damped mass, and between the spring on the mass's other side and a
    spring to a wall. Every variable Hopsan logs agrees with its run (hopsan_circuits/lossless_link.csv) within
    0.5 % of its range but the velocity of the first link's node: Hopsan's carries an undamped oscillation of
    its step's period, of amplitude F'(0)/k (0.063 m/s: started at t = 0, where its link, at rest, must move at
    F'/k at once), which its samples alias (a constant -0.063 m/s at 1e-6 s, +0.063, 0, -0.063, 0 in turn at
    0.02/10001 s); hydroservo gives the link's velocity, the mass's plus the stiff spring's rate F'/k, which is
    the mean of Hopsan's."""
    imp = import_hopsan(CIRCUITS / "lossless_link.hmf")
    assert imp.system["Link"].values["length"] == 0.0 and type(imp.system["Link2"]).__name__ == "RigidLink"
    columns = (CIRCUITS / "lossless_link.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    ref = np.loadtxt(CIRCUITS / "lossless_link.csv", delimiter=",", skiprows=1)
    t = ref[:, 0]
    result = imp.system.simulate(t_eval=t)
    by_hopsan = {hopsan: alias for alias, hopsan in imp.variables.items()}
    rate = -ref[:, columns.index("Mass#P1#Velocity")] + 2 * np.pi * 100.0 * np.cos(2 * np.pi * t) / 1e4
    compared = 0
    for i, column in enumerate(columns[1:], start=1):
        if column not in by_hopsan:
            continue
        y, y_ref = result[by_hopsan[column]], ref[:, i]
        if column in _LINK_NODE_VELOCITY:
            sign = 1.0 if column.startswith(("Link#P2", "Stiff#P1")) else -1.0  # end 2's node, or end 1's
            np.testing.assert_allclose(y_ref[1:] - sign * rate[1:], -sign * 0.0628, atol=5e-4)  # Hopsan's offset
            y_ref = sign * rate
        if column.endswith(("#Force", "#Value")) or column in _LINK_NODE_VELOCITY:  # the link starts at rest
            y, y_ref = y[1:], y_ref[1:]
        scale = max(float(np.ptp(y_ref)), 0.01 * float(np.max(np.abs(y_ref))), 1e-12)
        assert np.max(np.abs(y - y_ref)) <= 0.005 * scale, column
        compared += 1
    assert compared >= 40


def test_3d_lookup_table_matches_hopsan_and_refuses_a_malformed_table(tmp_path: Path) -> None:
    """Signal3DLookupTable, its table of 3 rows, 2 columns and 4 planes of unequal breakpoints and values that
    no multilinear function gives (hopsan_circuits/table_3d_data.csv), read by three sines that leave its
    breakpoints: the output agrees with Hopsan's run (hopsan_circuits/table_3d.csv) within 1e-6 of its range (the
    values paired with the breakpoints as Hopsan pairs them); a table whose last line announces more lines than it
    has is refused with the file named."""
    imp = import_hopsan(CIRCUITS / "table_3d.hmf")
    ref = np.loadtxt(CIRCUITS / "table_3d.csv", delimiter=",", skiprows=1)
    column = (CIRCUITS / "table_3d.csv").read_text(encoding="utf-8").splitlines()[0].split(",").index("LUT3#out#Value")
    result = imp.system.simulate(t_eval=ref[:, 0])
    assert np.max(np.abs(result["LUT3.out.Value"] - ref[:, column])) <= 1e-6 * np.ptp(ref[:, column])
    text = (CIRCUITS / "table_3d_data.csv").read_text(encoding="utf-8").replace("3,2,4,0", "3,2,5,0")
    (tmp_path / "table_3d_data.csv").write_text(text, encoding="utf-8")
    (tmp_path / "table_3d.hmf").write_text((CIRCUITS / "table_3d.hmf").read_text(encoding="utf-8"), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"LUT3 \(Signal3DLookupTable\): filename.*24 lines of data where the last "
                       r"line announces 3 x 2 x 5 = 30"):
        read_hopsan(tmp_path / "table_3d.hmf")


@pytest.mark.parametrize(
    ("kind", "params", "drive", "message"),
    [
        ("HydraulicQSource", {}, "in_p", r"in_p driven by a signal: Hopsan logs it as the node's pressure"),
        ("MechanicTranslationalCSource", {"in_z#Value": ("-1", "")}, None, r"in_z = -1 N s/m; only an impedance"),
        ("MechanicTranslationalQSource", {}, "in_f", r"in_f driven by a signal: Hopsan logs it as the node's force"),
        ("MechanicTranslationalQSource", {}, "in_v", r"in_v moves the node while in_x holds it at 0 m"),
        ("MechanicTranslationalQSource", {"in_v#Value": ("0.1", "")}, None, r"in_v moves the node"),
    ],
)
def test_tlm_sources_refuse_what_they_cannot_honour(
    tmp_path: Path, kind: str, params: dict, drive: str | None, message: str
) -> None:
    """A Q source's logged-only pressure or force driven by a signal, a mechanic C source's negative impedance,
    and a mechanic Q source moving its node at a fixed position are refused, each with why; the same sources
    without those settings import."""
    neighbour = {  # the component joined to the source: a Q one to a C source, a C one to a Q source
        "HydraulicCSource": ("HydraulicFlowSourceQ", "P1"), "HydraulicQSource": ("HydraulicTankC", "P1"),
        "MechanicTranslationalCSource": ("MechanicFixedPosition", "Pm1"),
        "MechanicTranslationalQSource": ("MechanicForceTransformer", "P1"),
    }[kind]
    components = [(kind, "S", params), (neighbour[0], "N", {}), ("SignalSineWave", "W", {})]
    connections = [("S.P1", f"N.{neighbour[1]}")]
    if drive is not None:
        connections.append(("W.out", f"S.{drive}"))
    path = tmp_path / "source.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=message):
        read_hopsan(path)
    path.write_text(_hmf([(kind, "S", {}), (neighbour[0], "N", {})], connections[:1]), encoding="utf-8")
    assert read_hopsan(path).t_end == 3.0



def test_geometric_orifices_map_to_the_blended_orifice_law(tmp_path: Path) -> None:
    """HydraulicOrificeG, HydraulicOrificeCheckValveG and HydraulicSlitOrifice: an Orifice with law = "blend", its
    laminar coefficient from Hopsan's geometry (k_lam = 2 del^2 dh^2 / (L visc), L = dh + 32 del^2 lo (3 - sf);
    the slit's 8 Ao^2 del^2 / (visc So sqrt(M))), the check valve's bores Ab forwards and Ao back; parameters that
    Hopsan's law divides by, when 0, and a discharge coefficient above 1 are refused with the component named."""
    v = _value
    components = [
        ("HydraulicOrificeG", "OG", {"Ao": v("2e-6"), "dh": v("0.001"), "lo": v("0.002"), "visc": v("0.04"),
                                     "del": v("0.2"), "sf": v("1"), "Cdt": v("0.7"), "rho": v("880")}),
        ("HydraulicOrificeCheckValveG", "CV", {"Ao": v("1e-6"), "Ab": v("4e-7"), "dh": v("0.001"), "lo": v("0.002"),
                                               "visc": v("0.04"), "del": v("0.2")}),
        ("HydraulicSlitOrifice", "SL", {"Ao": v("1e-6"), "So": v("0.004"), "lo": v("0.002"), "visc": v("0.04"),
                                        "del": v("0.2"), "sf": v("0")}),
    ]
    path = tmp_path / "orifices.hmf"
    path.write_text(_hmf(components, []), encoding="utf-8")
    system = read_hopsan(path)
    og, cv, sl = system["OG"], system["CV"], system["SL"]
    assert og.option("law") == "blend" and og.values["n_blend"] == 2.0 and sl.values["n_blend"] == 4.0
    assert np.pi * og.values["d"] ** 2 / 4 == pytest.approx(2e-6) and og.values["Cd"] == 0.7
    assert og.values["rho"] == 880.0 and og.values["d_back"] == 0.0
    big_l = 0.001 + 32 * 0.04 * 0.002 * 2
    assert og.values["k_lam"] == pytest.approx(2 * 0.04 * 1e-6 / (big_l * 0.04))
    assert np.pi * cv.values["d"] ** 2 / 4 == pytest.approx(4e-7) and np.pi * cv.values["d_back"] ** 2 / 4 == pytest.approx(1e-6)
    assert cv.values["k_lam"] == pytest.approx(2 * 0.04 * 1e-6 / ((0.001 + 32 * 0.04 * 0.002 * 3) * 0.04))
    assert cv.values["Cd"] == 0.67 and sl.values["Cd"] == 0.611
    big_m = 1e-12 + 64 * 0.2**4 * 0.002**2 * 9 * 0.004**2
    assert sl.values["k_lam"] == pytest.approx(8 * 1e-12 * 0.04 / (0.04 * 0.004 * np.sqrt(big_m)))
    components[0][2]["visc"] = v("0")
    components[2][2]["Cd"] = v("1.5")
    path.write_text(_hmf(components, []), encoding="utf-8")
    refused = r"OG \(HydraulicOrificeG\): visc = 0; only values above 0.*SL \(HydraulicSlitOrifice\): Cd = 1.5; a discharge"
    with pytest.raises(ModelFileError, match=refused):
        read_hopsan(path)


def test_poppet_and_shuttle33_valves_map_to_an_orifice_damped_spool(tmp_path: Path) -> None:
    """Hydraulic22PoppetValve: a SpoolOrificeDamped (areas pi d_1^2/4 at PN and the annulus at PS, chamber
    pi d_2^2/4 drained to PC through d_d) and a TwoWayValve PS-PN of C_q pi d_1 f sqrt(2/rho); Hydraulic33ShuttleValve:
    a SpoolOrificeDamped whose damping orifices d_1 and d_2 are in series (damping_flow = none), flipped into a
    ThreeWayValve. The start position xv_out is limited to the stroke; a stroke of 0 is refused."""
    v = _value
    components = [
        ("Hydraulic22PoppetValve", "PV", {"d_1": v("0.008"), "d_2": v("0.01"), "k": v("3e4"), "F_0": v("50"),
                                          "f": v("0.5"), "x_vmax": v("0.004"), "d_d": v("0.0002"), "xv_out": v("0.02")}),
        ("Hydraulic33ShuttleValve", "SV", {"d": v("0.012"), "f_pa": v("0.2"), "f_at": v("0.3"), "x_pa": v("1e-4"),
                                           "x_at": v("-2e-4"), "d_1": v("0.001"), "d_2": v("0.002"), "xv_out": v("-0.003"),
                                           "rho": v("880")}),
    ]
    ports = ["PV.PS", "PV.PN", "PV.PC", "SV.PP", "SV.PT", "SV.PA"]
    components += [("HydraulicTankC", f"T{i}", {}) for i in range(len(ports))]
    connections = [(port, f"T{i}.P1") for i, port in enumerate(ports)]
    path = tmp_path / "valves.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    system = read_hopsan(path)
    poppet, seat = system["PV_poppet"].values, system["PV"].values
    assert poppet["A_1"] == pytest.approx(np.pi * 0.008**2 / 4) and poppet["A_c"] == pytest.approx(np.pi * 0.01**2 / 4)
    assert poppet["A_1"] + poppet["A_2"] == pytest.approx(poppet["A_c"]) and poppet["F_0"] == 50.0 and poppet["k_s"] == 3e4
    assert poppet["K_d"] == pytest.approx(0.67 * np.pi * 0.0002**2 / 4 * np.sqrt(2 / 870))
    assert (poppet["x_min"], poppet["x_max"], poppet["x0"]) == (0.0, 0.004, 0.004)
    assert seat["c_v"] == pytest.approx(0.67 * np.pi * 0.008 * 0.5 * np.sqrt(2 / 870)) and seat["x_AB"] == 0.0
    spool, edges = system["SV_spool"], system["SV"].values
    k_1, k_2 = (0.67 * np.pi * d**2 / 4 * np.sqrt(2 / 880) for d in (0.001, 0.002))
    assert spool.option("damping_flow") == "none" and spool.values["x0"] == -0.003
    assert spool.values["K_d"] == pytest.approx(k_1 * k_2 / np.hypot(k_1, k_2))
    assert spool.values["A_1"] == spool.values["A_c"] == pytest.approx(np.pi * 0.012**2 / 4)
    assert (spool.values["x_min"], spool.values["x_max"]) == (-0.01, 0.01) and system["SV_flip"].values["K"] == -1.0
    assert edges["c_PA"] == pytest.approx(0.67 * 0.2 * np.pi * 0.012 * np.sqrt(2 / 880))
    assert edges["c_AT"] == pytest.approx(0.67 * 0.3 * np.pi * 0.012 * np.sqrt(2 / 880))
    assert (edges["x_PA"], edges["x_AT"]) == (1e-4, -2e-4)
    components[0][2]["x_vmax"] = v("0")
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"PV \(Hydraulic22PoppetValve\): x_vmax = 0 m"):
        read_hopsan(path)


def test_special_valve43_63oc_and_43ls_map_to_a_four_way_valve_on_their_limited_input(tmp_path: Path) -> None:
    """HydraulicValve43 (Special): a Saturation of xv to ±Xvmax and a FourWayValve of c_v = Cq Fr pi Sd sqrt(2/rho),
    every edge underlapped by Xap0, its transition pressure plam (D_h chosen so); HydraulicValve63OC's edges
    overlapped by Xap0 and its open centre a TwoWayValve of Cq Froc pi Sd sqrt(2/rho) open below |xv| = Xoc0;
    HydraulicValve43LS's load-sensing edges a ThreeWayValve (LS-A, LS-B, Ks wls wide) and a TwoWayValve (LS-T)
    between Pls and PressureSources holding A's, B's and T's pressures; Xat0 unlike Xap0 is refused."""
    from hydroservo.laws.orifice import transition_pressure

    v = _value
    params = {"rho": v("860"), "Sd": v("0.012"), "Frap": v("0.5"), "Frat": v("0.5"), "Frbp": v("0.5"), "Frbt": v("0.5"),
              "Xap0": v("3e-4"), "Xat0": v("3e-4"), "Xbp0": v("3e-4"), "Xbt0": v("3e-4"), "Xvmax": v("0.004"),
              "plam": v("2e5")}
    ports = ["V.Pp", "V.Pt", "V.Pa", "V.Pb"]
    components = [("HydraulicValve43", "V", params), *(("HydraulicTankC", f"T{i}", {}) for i in range(4))]
    connections = [(port, f"T{i}.P1") for i, port in enumerate(ports)]
    path = tmp_path / "valve43.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    system = read_hopsan(path)
    valve = system["V"].values
    assert valve["c_v"] == pytest.approx(0.67 * 0.5 * np.pi * 0.012 * np.sqrt(2 / 860))
    assert [valve[k] for k in ("x_PA", "x_AT", "x_PB", "x_BT")] == [-3e-4] * 4
    assert transition_pressure(valve["D_h"], valve["rho"], valve["nu"], valve["lambda_crit"]) == pytest.approx(2e5)
    assert (system["V_xv"].values["lower"], system["V_xv"].values["upper"]) == (-0.004, 0.004)
    oc = {**params, "Froc": v("0.25"), "Xoc0": v("0.002")}
    oc_ports = ["W.Pp", "W.Pt", "W.Pa", "W.Pb", "W.Pocp", "W.Poct"]
    oc_components = [("HydraulicValve63OC", "W", oc), *(("HydraulicTankC", f"U{i}", {}) for i in range(6))]
    oc_connections = [(port, f"U{i}.P1") for i, port in enumerate(oc_ports)]
    path.write_text(_hmf(oc_components, oc_connections), encoding="utf-8")
    system = read_hopsan(path)
    assert [system["W"].values[k] for k in ("x_PA", "x_AT", "x_PB", "x_BT")] == [3e-4] * 4  # overlaps here
    centre = system["W_centre"].values
    assert centre["c_v"] == pytest.approx(0.67 * 0.25 * np.pi * 0.012 * np.sqrt(2 / 860)) and centre["x_AB"] == -0.002
    assert transition_pressure(centre["D_h"], centre["rho"], centre["nu"], centre["lambda_crit"]) == pytest.approx(2e5)
    ls = {**params, "wls": v("0.003"), "Xlsa0": v("1e-4"), "Xlsb0": v("2e-4"), "Xls0": v("5e-4"), "Xvlsmax": v("0.002")}
    ls_ports = ["L.Pp", "L.Pt", "L.Pa", "L.Pb", "L.Pls"]
    ls_components = [("HydraulicValve43LS", "L", ls), *(("HydraulicTankC", f"U{i}", {}) for i in range(5))]
    path.write_text(_hmf(ls_components, [(port, f"U{i}.P1") for i, port in enumerate(ls_ports)]), encoding="utf-8")
    system = read_hopsan(path)
    edges, lst = system["L_ls"].values, system["L_lst"].values
    assert edges["c_PA"] == edges["c_AT"] == lst["c_v"] == pytest.approx(0.67 * 0.003 * np.sqrt(2 / 860))
    assert (edges["x_PA"], edges["x_AT"], lst["x_AB"]) == (1e-4, 2e-4, -5e-4)
    assert (system["L_xls"].values["lower"], system["L_xls"].values["upper"]) == (-0.002, 0.002)
    assert system["L_mirror_a"].values["p0"] == pytest.approx(-101325.0)
    params["Xat0"] = v("1e-4")
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"V \(HydraulicValve43\): Xat0 = 0.0001 m differ from Xap0 = 0.0003 m"):
        read_hopsan(path)


def test_relief2_valve_g_maps_to_a_relief_valve_whose_spool_has_mass(tmp_path: Path) -> None:
    """HydraulicPressureRelief2ValveG: HydraulicPressureReliefValveG's characteristics with the whole circumference
    open (w = pi Dv sin phi) and spool = "mass", tau_m = Mv/Bv; its outputs xv and dxv the opening and its rate
    times Xvmax (its own default 0.03 m); a spool mass of 0 is refused."""
    v = _value
    params = {"pref": v("8e6"), "Dv": v("0.012"), "Bv": v("50"), "Mv": v("0.02"), "Cq": v("0.7"), "phi": v("1.0"),
              "ks": v("2e4"), "p0": v("2e5"), "rho": v("860")}
    components = [("HydraulicPressureRelief2ValveG", "R", params), ("HydraulicTankC", "T1", {}),
                  ("HydraulicTankC", "T2", {})]
    connections = [("R.P1", "T1.P1"), ("R.P2", "T2.P1")]
    path = tmp_path / "relief2.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    valve = imp.system["R"]
    c = 0.7 * np.pi * 0.012 * np.sin(1.0) * np.sqrt(2 / 860)  # K per metre of opening
    assert valve.option("spool") == "mass" and valve.option("pilot") == "drop"
    assert valve.values["tau_m"] == pytest.approx(0.02 / 50) and valve.values["tau"] == pytest.approx(50 / 2e4)
    assert valve.values["q_nom"] == pytest.approx(c * 0.03 * np.sqrt(valve.values["p_nom"]))
    assert valve.values["p_crack"] == 8e6 and valve.values["p_tr"] == 2e5
    assert imp.variables["R.dxv.Value"] == "R#dxv#Value" and imp.variables["R.xv.Value"] == "R#xv#Value"
    params["Mv"] = v("0")
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"R \(HydraulicPressureRelief2ValveG\): Mv = 0"):
        read_hopsan(path)


def test_motor_jload_maps_to_a_motor_with_its_inertia(tmp_path: Path) -> None:
    """HydraulicMotorJload: a Motor of D = Dm per revolution, C_im = Cim, B_m = Bm, J = Jm, its flow not clamped
    (inlet = "free"), its shaft Pm1; Jm of 0 is refused."""
    v = _value
    params = {"Dm": v("3e-5"), "Cim": v("2e-11"), "Bm": v("0.3"), "Jm": v("0.02")}
    components = [("HydraulicMotorJload", "M", params), ("HydraulicTankC", "T1", {}), ("HydraulicTankC", "T2", {}),
                  ("MechanicTorqueTransformer", "L", {})]
    connections = [("M.P1", "T1.P1"), ("M.P2", "T2.P1"), ("M.Pm1", "L.P1")]
    path = tmp_path / "motor.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    motor = read_hopsan(path)["M"]
    assert motor.values["D"] == pytest.approx(3e-5 / (2 * np.pi)) and motor.values["C_im"] == 2e-11
    assert (motor.values["B_m"], motor.values["J"]) == (0.3, 0.02) and motor.option("inlet") == "free"
    params["Jm"] = v("0")
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"M \(HydraulicMotorJload\): Jm = 0"):
        read_hopsan(path)


def test_hopsan_piston_maps_to_a_cylinder_without_friction_leakage_or_stops(tmp_path: Path) -> None:
    """HydraulicPiston: a Cylinder of A1, A2, V01, V02 + A2 SL (chamber 2 measured from the other end), betae, no
    friction, leakage or stops, its cavity floored at the ports only (pressure_floor = "cavity-ports"), its rod
    Pm1; a stroke of 0 is refused."""
    v = _value
    params = {"A1": v("2e-3"), "A2": v("1e-3"), "V01": v("3e-4"), "V02": v("4e-4"), "SL": v("0.4"), "betae": v("8e8")}
    components = [("HydraulicPiston", "P", params), ("HydraulicLaminarOrifice", "O1", {}),
                  ("HydraulicLaminarOrifice", "O2", {}), ("MechanicTranslationalMass", "M", {})]
    connections = [("P.P1", "O1.P1"), ("P.P2", "O2.P1"), ("P.Pm1", "M.P1")]
    path = tmp_path / "piston.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    cyl = read_hopsan(path)["P"]
    assert (cyl.values["A_A"], cyl.values["A_B"], cyl.values["V_A0"]) == (2e-3, 1e-3, 3e-4)
    assert cyl.values["V_B0"] == pytest.approx(4e-4 + 1e-3 * 0.4) and cyl.values["beta_e"] == 8e8
    assert (cyl.values["B_p"], cyl.values["C_Li"], cyl.values["k_stop"], cyl.values["c_stop"]) == (0, 0, 0, 0)
    assert cyl.option("pressure_floor") == "cavity-ports"
    params["SL"] = v("0")
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"P \(HydraulicPiston\): SL = 0"):
        read_hopsan(path)


def test_fuel_tank_maps_to_a_head_tank(tmp_path: Path) -> None:
    """HydraulicFuelTankG: a HeadTank of p0 (absolute), rhofuel, gx, hf, massfuelmax, its mass from massfuel0
    within [-1e-4 kg, massfuel0], vacuum when empty; its outputs massfuel and consfuel; massfuelmax of 0 refused."""
    v = _value
    params = {"gx": v("9.81"), "rhofuel": v("750"), "p0": v("2e5"), "hf": v("3"), "massfuel0": v("40"),
              "massfuelmax": v("80")}
    components = [("HydraulicFuelTankG", "F", params), ("HydraulicLaminarOrifice", "O", {}), ("HydraulicTankC", "T", {})]
    connections = [("F.PT", "O.P1"), ("O.P2", "T.P1")]
    path = tmp_path / "fuel.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    tank = imp.system["F"].values
    assert tank["p0"] == pytest.approx(2e5 - 101325.0) and tank["p_vac"] == pytest.approx(-101325.0)
    assert (tank["rho"], tank["g"], tank["h_full"], tank["m_full"], tank["m0"]) == (750, 9.81, 3, 80, 40)
    assert (tank["m_min"], tank["m_max"]) == (-1e-4, 40)
    assert imp.variables["F.massfuel.Value"] == "F#massfuel#Value"
    params["massfuelmax"] = v("0")
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"F \(HydraulicFuelTankG\): rhofuel = 750 kg/m\^3, massfuelmax = 0"):
        read_hopsan(path)


def test_pressure_controlled_pump_g_maps_to_the_g_regulator_and_follows_hopsans_run() -> None:
    """HydraulicPressureControlledPumpG: a LoadSensingPump with regulator = "g" (its parameters by Hopsan's names),
    on hopsan_circuits/pressure_controlled_pump_g.hmf (the circuit of pressure_controlled_pump with the G pump:
    it destrokes from its start flow to its minimum as its outlet fills, then the orifice closes and a flow is
    drawn). Every trace within 0.5 % of its range but the pump's: its displacement flow qp (and eps) lags Hopsan's
    by about 1.5 ms while the outlet pressure ramps at the start, 1.1 % of its range (the regulator takes the
    rates of its error and lead through lags of tau_v/100, G_LAG), its port flows 0.53 %; known, not tuned."""
    imp = import_hopsan(CIRCUITS / "pressure_controlled_pump_g.hmf")
    pump = imp.system["Pump"]
    assert pump.option("regulator") == "g" and pump.option("inlet") == "free"
    assert pump.values["D"] == pytest.approx(1e-4 / (2 * np.pi)) and pump.values["omega"] == 157.0
    assert (pump.values["l_p"], pump.values["R_p"], pump.values["omega_p1"]) == (1.83e10, 1.68e10, 13.3)
    assert (pump.values["tau_v"], pump.values["t_p"], pump.values["t_m"], pump.values["eps_min"]) == (0.05, 0.02, 0.03, 0.05)
    columns = (CIRCUITS / "pressure_controlled_pump_g.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    ref = np.loadtxt(CIRCUITS / "pressure_controlled_pump_g.csv", delimiter=",", skiprows=1)
    result = _simulate_flagged(imp.system, "pressure_controlled_pump_g", ref[:, 0])
    by_hopsan = {hopsan: alias for alias, hopsan in imp.variables.items()}
    worst = {}
    for i, column in enumerate(columns[1:], start=1):
        y, y_ref = np.asarray(result[by_hopsan[column]])[1:], ref[1:, i]
        scale = max(float(np.ptp(y_ref)), 0.01 * float(np.max(np.abs(y_ref))), 1e-12)
        worst[column] = float(np.max(np.abs(y - y_ref))) / scale
    known = {c: d for c, d in worst.items() if c.startswith(("Pump#", "TS#")) and not c.endswith("#Pressure")}
    assert max(known.values()) <= 0.012 and max(known.values()) > 0.005  # the known lag, not more
    assert all(d <= 0.005 for c, d in worst.items() if c not in known), worst

def _value(text: str, unit: str = "") -> tuple[str, str]:
    return (text, unit)


def test_signal_filters_sources_and_routes_map_with_hopsans_parameters(tmp_path: Path) -> None:
    """Each filter, source and route of Hopsan's signal library mapped so far, with its parameters by Hopsan's
    names and its ports (in, out, in1..in4, route), checked at known times against Hopsan's laws: a high pass
    answers a step at 1 s with exp(-omega (t - 1)); the lead-lag k (s/w_n + 1)/(s/w_d + 1) with
    k (1 + (w_d/w_n - 1) exp(-w_d (t - 1))); the transfer functions' coefficients a_i, b_i; a square wave is
    y_0 + y_A on the first half of each period; a pulse wave y_0 + y_A on the first D of each dT; a staircase
    H_step per W_step; a step with exponential delay y_0 + y_A exp(-(t - t_step)/tao); the time is Hopsan's
    (the model starts at -1 s); the routes choose in1, in2, ... as route passes each limit."""
    v = _value
    components = [
        ("SignalStep", "Step", {"y_0#Value": v("0"), "y_A#Value": v("1"), "t_step#Value": v("0")}),
        ("SignalHP1Filter", "HP", {"omega": v("5")}),
        ("SignalFirstOrderFilter", "LL", {"k": v("2"), "omega_num": v("5"), "omega_den": v("30")}),
        ("SignalLP2Filter", "LP2", {"omega": v("20"), "delta": v("0.5")}),
        ("SignalFirstOrderTransferFunction", "TF1", {"a_1": v("0"), "a_0": v("3"), "b_1": v("0.1"), "b_0": v("1")}),
        ("SignalSecondOrderTransferFunction", "TF2", {"a_2": v("2"), "a_1": v("3"), "a_0": v("4"), "b_2": v("1"),
                                                      "b_1": v("5"), "b_0": v("6")}),
        ("SignalSquareWave", "Sq", {"y_0#Value": v("1"), "y_A#Value": v("2"), "f#Value": v("0.5"), "t_start#Value": v("0")}),
        ("SignalPulseWave", "PW", {"y_0#Value": v("0"), "y_A#Value": v("1"), "t_start#Value": v("0"), "dT#Value": v("2"),
                                   "D#Value": v("0.25")}),
        ("SignalStaircase", "St", {"T_start#Value": v("0"), "H_step#Value": v("1"), "W_step#Value": v("1")}),
        ("SignalStepExponentialDelay", "SE", {"y_0#Value": v("1"), "y_A#Value": v("2"), "tao#Value": v("0.5"),
                                              "t_step#Value": v("0")}),
        ("SignalTime", "Time", {}),
        ("SignalDualRoute", "R2", {"limit": v("1.5")}),
        ("SignalTripleRoute", "R3", {"limit12": v("0.5"), "limit23": v("1.5")}),
        ("SignalQuadRoute", "R4", {"limit12": v("0.5"), "limit23": v("1.5"), "limit34": v("2.5")}),
        *[("SignalConstant", f"C{i}", {"y#Value": v(str(10 * i))}) for i in (1, 2, 3, 4)],
    ]
    connections = [("Step.out", f"{f}.in") for f in ("HP", "LL", "LP2", "TF1", "TF2")]
    for route, n in (("R2", 2), ("R3", 3), ("R4", 4)):
        connections += [("St.out", f"{route}.route"), *((f"C{i}.y", f"{route}.in{i}") for i in range(1, n + 1))]
    path = tmp_path / "signals.hmf"
    path.write_text(_hmf(components, connections).replace('start="0"', 'start="-1"'), encoding="utf-8")
    imp = import_hopsan(path)
    kinds = {hopsan: became for hopsan, _, became in imp.mapping}
    assert kinds["HP"] == "TransferFunction HP" and kinds["R4"] == "Selector R4" and kinds["Sq"] == "Square Sq"
    assert kinds["PW"] == "PulseWave PW" and kinds["St"] == "Staircase St" and kinds["SE"] == "DecayingStep SE"
    t = np.array([0.5, 1.25, 1.75, 2.5, 3.2])  # hydroservo's time: Hopsan's plus 1 s, the step at 1 s
    r = imp.system.simulate(t_eval=t, accuracy=1e-8)
    tau = t - 1.0
    np.testing.assert_allclose(r["HP.out.Value"], np.where(tau >= 0, np.exp(-5 * tau), 0.0), atol=1e-6)
    ll = 2 * (1 + (30 / 5 - 1) * np.exp(-30 * tau))
    np.testing.assert_allclose(r["LL.out.Value"], np.where(tau >= 0, ll, 0.0), atol=1e-5)
    wd = 20 * np.sqrt(0.75)
    lp2 = 1 - np.exp(-10 * tau) * (np.cos(wd * tau) + np.sin(wd * tau) / np.sqrt(3))
    np.testing.assert_allclose(r["LP2.out.Value"], np.where(tau >= 0, lp2, 0.0), atol=1e-5)
    np.testing.assert_allclose(r["TF1.out.Value"], np.where(tau >= 0, 3 * (1 - np.exp(-10 * tau)), 0.0), atol=1e-5)
    tf2 = 2 - 4 / 3 - 3 * np.exp(-2 * tau) + 13 / 3 * np.exp(-3 * tau)
    np.testing.assert_allclose(r["TF2.out.Value"], np.where(tau >= 0, tf2, 0.0), atol=1e-5)
    hopsan_t = t - 1.0
    np.testing.assert_allclose(r["Time.out.Value"], hopsan_t, atol=1e-12)
    np.testing.assert_allclose(r["Sq.out.Value"], np.where(hopsan_t < 0, 1, np.where(hopsan_t % 2 < 1, 3, -1)))
    np.testing.assert_allclose(r["PW.out.Value"], np.where((hopsan_t > 0) & (hopsan_t % 2 < 0.5), 1, 0))
    np.testing.assert_allclose(r["St.out.Value"], np.floor(np.clip(hopsan_t, 0, None)))
    np.testing.assert_allclose(r["SE.out.Value"], np.where(hopsan_t >= 0, 1 + 2 * np.exp(-hopsan_t / 0.5), 1), atol=1e-12)
    stairs = np.floor(np.clip(hopsan_t, 0, None))  # 0, 0, 0, 1, 2
    np.testing.assert_allclose(r["R2.out.Value"], np.where(stairs < 1.5, 10, 20))
    np.testing.assert_allclose(r["R3.out.Value"], np.choose(np.minimum(stairs, 2).astype(int), [10, 20, 30]))
    np.testing.assert_allclose(r["R4.out.Value"], np.choose(np.minimum(stairs, 3).astype(int), [10, 20, 30, 40]))


def test_filters_with_output_limits_and_sources_before_the_start_are_refused(tmp_path: Path) -> None:
    v = _value
    components = [
        ("SignalHP1Filter", "HP", {"omega": v("5"), "y_max": v("1")}),
        ("SignalSquareWave", "Sq", {"t_start#Value": v("-2")}),
        ("SignalSecondOrderTransferFunction", "TF2", {"b_2": v("0"), "b_1": v("0"), "a_2": v("0")}),
    ]
    path = tmp_path / "limits.hmf"
    path.write_text(_hmf(components, []), encoding="utf-8")
    with pytest.raises(ModelFileError) as err:
        read_hopsan(path)
    text = str(err.value)
    assert "HP (SignalHP1Filter): a filter with output limits" in text
    assert "Sq (SignalSquareWave): t_start = -2 s, before the run's start" in text
    assert "TF2 (SignalSecondOrderTransferFunction): a transfer function with no s term" in text


def _valve_circuit(kind: str, ports: dict[str, float], params: dict, command: str | None) -> tuple[str, list, list]:
    """A Hopsan valve of type ``kind`` named V, each port on a pressure source of its own (absolute Pa), its
    input ``in`` driven by a constant ``command`` (None: left at its start value)."""
    components: list = [(kind, "V", params)]
    connections: list = []
    for port, p in ports.items():
        components.append(("HydraulicPressureSourceC", f"S{port}", {"p#Value": (repr(p), "Pa")}))
        connections.append((f"V.{port}", f"S{port}.P1"))
    if command is not None:
        components.append(("SignalConstant", "Cmd", {"y#Value": (command, "")}))
        connections.append(("Cmd.y", "V.in"))
    return kind, components, connections


def test_spool_valves_map_to_the_four_way_valves_edges_with_hopsans_laps_and_spool(tmp_path: Path) -> None:
    """Hopsan's 2/2, 3/2, 3/3 and 4/2 spool valves ([Hopsan2026] FlowControlValves/, DirectionalValves/), each
    held 0.3 s (the spool settled: omega_h 100 rad/s, critically damped) at a command, against Hopsan's law
    q = C_q f π d x √(2/ρ) √Δp per open edge (x its opening; turbulent to about 45 Pa, D_h 1 mm at flow number 10).
    The 2/2 valve's desired position -1 mm is limited to 0 (closed, xv 0); the on/off valves open fully for in
    above 0.5 and close at 0.5; Hydraulic42Valve never opens P-B or A-T; Hydraulic42Valve2 at half stroke opens all
    four edges by half of it."""
    from hydroservo.laws.orifice import transition_pressure

    p_tr = transition_pressure(1e-3, 870.0, 32e-6, 10.0)

    def q(f: float, d: float, x: float, dp: float) -> float:
        return 0.67 * f * np.pi * d * x * np.sqrt(2.0 / 870.0) * dp / (dp * dp + p_tr * p_tr) ** 0.25

    v = _value
    pa, pb, ps, pt = 60e5, 30e5, 100e5, 1e5
    cases = [
        (_valve_circuit("Hydraulic22Valve", {"PP": ps, "PA": pa}, {"x_vmax#Value": v("0.002")}, "-0.001"),
         {"V.PA.Flow": 0.0, "V.xv.Value": 0.0}),
        (_valve_circuit("Hydraulic22Valve", {"PP": ps, "PA": pa}, {"x_vmax#Value": v("0.002"), "f#Value": v("0.5")},
                        "0.0015"),
         {"V.PA.Flow": q(0.5, 0.01, 0.0015, ps - pa), "V.xv.Value": 0.0015}),
        (_valve_circuit("Hydraulic22DirectionalValve", {"P1": ps, "P2": pa}, {"d#Value": v("0.02")}, "1"),
         {"V.P2.Flow": q(1.0, 0.02, 0.01, ps - pa), "V.xv.Value": 0.01}),
        (_valve_circuit("Hydraulic22DirectionalValve", {"P1": ps, "P2": pa}, {}, "0.5"),
         {"V.P2.Flow": 0.0, "V.xv.Value": 0.0}),
        (_valve_circuit("Hydraulic32DirectionalValve", {"PP": ps, "PT": pt, "PA": pa}, {}, "0"),
         {"V.PA.Flow": -q(1.0, 0.01, 0.01, pa - pt), "V.PT.Flow": q(1.0, 0.01, 0.01, pa - pt), "V.PP.Flow": 0.0}),
        (_valve_circuit("Hydraulic33Valve", {"PP": ps, "PT": pt, "PA": pa},
                        {"f_pa#Value": v("0.5"), "x_pa#Value": v("0.001")}, "0.004"),
         {"V.PA.Flow": q(0.5, 0.01, 0.003, ps - pa), "V.PT.Flow": 0.0, "V.xv.Value": 0.004}),
        (_valve_circuit("Hydraulic33Valve", {"PP": ps, "PT": pt, "PA": pa}, {"x_at#Value": v("-0.001")}, "-0.02"),
         {"V.PA.Flow": -q(1.0, 0.01, 0.011, pa - pt), "V.xv.Value": -0.01}),
        (_valve_circuit("Hydraulic42Valve", {"PP": ps, "PT": pt, "PA": pa, "PB": pb}, {}, "0.004"),
         {"V.PA.Flow": q(1.0, 0.01, 0.004, ps - pa), "V.PB.Flow": -q(1.0, 0.01, 0.004, pb - pt)}),
        (_valve_circuit("Hydraulic42Valve2", {"PP": ps, "PT": pt, "PA": pa, "PB": pb}, {}, "0.005"),
         {"V.PA.Flow": q(1.0, 0.01, 0.005, ps - pa) - q(1.0, 0.01, 0.005, pa - pt),
          "V.PB.Flow": q(1.0, 0.01, 0.005, ps - pb) - q(1.0, 0.01, 0.005, pb - pt)}),
        (_valve_circuit("Hydraulic42DirectionalValve", {"PP": ps, "PT": pt, "PA": pa, "PB": pb}, {}, "0"),
         {"V.PA.Flow": -q(1.0, 0.01, 0.01, pa - pt), "V.PB.Flow": q(1.0, 0.01, 0.01, ps - pb), "V.xv.Value": 0.0}),
    ]
    for i, ((kind, components, connections), expected) in enumerate(cases):
        path = tmp_path / f"valve{i}.hmf"
        path.write_text(_hmf(components, connections), encoding="utf-8")
        imp = import_hopsan(path)
        assert dict((h, t) for h, t, _ in imp.mapping)["V"] == kind
        r = imp.system.simulate(t_eval=[0.0, 0.3], accuracy=1e-8)
        for alias, value in expected.items():
            assert float(r[alias][-1]) == pytest.approx(value, rel=1e-6, abs=1e-12), (kind, alias)


def test_hopsans_open_centre_valve_is_the_43_valve_with_a_centre_edge_closing_towards_either_end(
    tmp_path: Path,
) -> None:
    """[Hopsan2026] FlowControlValves/HydraulicOpenCenterValve.hpp, each case held 0.3 s at a command: the 4/3
    valve's edges (P-A and B-T open as x_v - lap, P-B and A-T as -x_v - lap) and the centre edge C1-C2 open as
    x_vmax - limit(|x_v| - x_cc, 0, x_vmax), each C_q f π d x √(2/ρ) √Δp; the command is limited to the stroke. A
    stroke of 0 is refused."""
    from hydroservo.laws.orifice import transition_pressure

    p_tr = transition_pressure(1e-3, 870.0, 32e-6, 10.0)

    def q(f: float, x: float, dp: float) -> float:
        return 0.67 * f * np.pi * 0.01 * max(x, 0.0) * np.sqrt(2.0 / 870.0) * dp / (dp * dp + p_tr * p_tr) ** 0.25

    v = _value
    ports = {"PP": 100e5, "PT": 1e5, "PA": 60e5, "PB": 30e5, "PC1": 80e5, "PC2": 20e5}
    cases = [  # x_cc, command, x_v, centre opening
        ("-0.001", "0.004", 0.004, 0.005),  # the centre closes 1 mm before the end of the stroke
        ("0.003", "-0.002", -0.002, 0.01),  # within x_cc the centre stays open by x_vmax
        ("0.003", "-0.006", -0.006, 0.007),
        ("-1e-6", "0.02", 0.01, 0.0),  # limited to the stroke: closed
    ]
    for i, (x_cc, command, x, centre) in enumerate(cases):
        params = {"x_cc#Value": v(x_cc), "f_cc#Value": v("0.5")}
        kind, components, connections = _valve_circuit("HydraulicOpenCenterValve", ports, params, command)
        path = tmp_path / f"oc{i}.hmf"
        path.write_text(_hmf(components, connections), encoding="utf-8")
        imp = import_hopsan(path)
        assert dict((h, t) for h, t, _ in imp.mapping)["V"] == kind
        r = imp.system.simulate(t_eval=[0.0, 0.3], accuracy=1e-8)
        lap = -1e-6
        q_pa, q_bt = q(1.0, x - lap, 100e5 - 60e5), q(1.0, x - lap, 30e5 - 1e5)
        q_pb, q_at = q(1.0, -x - lap, 100e5 - 30e5), q(1.0, -x - lap, 60e5 - 1e5)
        expected = {
            "V.xv.Value": x, "V.PA.Flow": q_pa - q_at, "V.PB.Flow": q_pb - q_bt, "V.PT.Flow": q_at + q_bt,
            "V.PP.Flow": -q_pa - q_pb, "V.PC2.Flow": q(0.5, centre, 80e5 - 20e5),
            "V.PC1.Flow": -q(0.5, centre, 80e5 - 20e5),
        }
        for alias, value in expected.items():
            assert float(r[alias][-1]) == pytest.approx(value, rel=1e-6, abs=1e-12), (x_cc, command, alias)
    _, components, connections = _valve_circuit("HydraulicOpenCenterValve", ports, {"x_vmax#Value": v("0")}, "0")
    path = tmp_path / "oc_refused.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"V \(HydraulicOpenCenterValve\): x_vmax = 0 m; only a stroke above 0"):
        read_hopsan(path)


def test_hopsans_43_valves_with_a_neutral_to_tank_centre_add_edges_closing_within_p_c_of_the_stroke(
    tmp_path: Path,
) -> None:
    """[Hopsan2026] FlowControlValves/Hydraulic43ValveNeutralSupplyToTank.hpp and Hydraulic43ValveNeutralToTank.hpp,
    each case held 0.3 s at a command: the 4/3 valve's edges and, open at the centre by x_c = max(x_vmax - |x_v|/p_c,
    0), an edge P-T (SupplyToTank) or the edges A-T and B-T (NeutralToTank), each C_q f_c π d x_c √(2/ρ) √Δp. A
    p_c of 0 is refused."""
    from hydroservo.laws.orifice import transition_pressure

    p_tr = transition_pressure(1e-3, 870.0, 32e-6, 10.0)

    def q(f: float, x: float, dp: float) -> float:
        return 0.67 * f * np.pi * 0.01 * max(x, 0.0) * np.sqrt(2.0 / 870.0) * dp / (dp * dp + p_tr * p_tr) ** 0.25

    v = _value
    pp, pt, pa, pb = 100e5, 1e5, 60e5, 30e5
    ports = {"PP": pp, "PT": pt, "PA": pa, "PB": pb}
    cases = [  # type, p_c, command, x_v, centre opening
        ("Hydraulic43ValveNeutralSupplyToTank", "0.5", "0.0", 0.0, 0.01),  # at rest the centre is open by x_vmax
        ("Hydraulic43ValveNeutralSupplyToTank", "0.5", "-0.002", -0.002, 0.006),
        ("Hydraulic43ValveNeutralSupplyToTank", "0.5", "0.007", 0.007, 0.0),  # closed from |x_v| = p_c x_vmax on
        ("Hydraulic43ValveNeutralToTank", "0.25", "0.001", 0.001, 0.006),
        ("Hydraulic43ValveNeutralToTank", "0.25", "-0.02", -0.01, 0.0),  # the command limited to the stroke
    ]
    for i, (kind, p_c, command, x, centre) in enumerate(cases):
        params = {"p_c#Value": v(p_c), "f_c#Value": v("0.3"), "delta_h#Value": v("1")}
        _, components, connections = _valve_circuit(kind, ports, params, command)
        path = tmp_path / f"neutral{i}.hmf"
        path.write_text(_hmf(components, connections), encoding="utf-8")
        imp = import_hopsan(path)
        assert dict((h, t) for h, t, _ in imp.mapping)["V"] == kind
        r = imp.system.simulate(t_eval=[0.0, 0.3], accuracy=1e-8)
        lap = -1e-6
        q_pa, q_bt = q(1.0, x - lap, pp - pa), q(1.0, x - lap, pb - pt)
        q_pb, q_at = q(1.0, -x - lap, pp - pb), q(1.0, -x - lap, pa - pt)
        if kind.endswith("SupplyToTank"):
            q_pt = q(0.3, centre, pp - pt)
        else:
            q_pt = 0.0
            q_at += q(0.3, centre, pa - pt)
            q_bt += q(0.3, centre, pb - pt)
        expected = {
            "V.xv.Value": x, "V.PA.Flow": q_pa - q_at, "V.PB.Flow": q_pb - q_bt, "V.PT.Flow": q_at + q_bt + q_pt,
            "V.PP.Flow": -q_pa - q_pb - q_pt,
        }
        for alias, value in expected.items():
            assert float(r[alias][-1]) == pytest.approx(value, rel=1e-6, abs=1e-12), (kind, command, alias)
    _, components, connections = _valve_circuit("Hydraulic43ValveNeutralToTank", ports, {"p_c#Value": v("0")}, "0")
    path = tmp_path / "neutral_refused.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"V \(Hydraulic43ValveNeutralToTank\): x_vmax = 0.01 m, p_c = 0; only"):
        read_hopsan(path)


def test_hopsans_valve33_is_a_three_way_valve_with_its_underlap_and_laminar_onset(tmp_path: Path) -> None:
    """[Hopsan2026] Special/HydraulicValve33.hpp: the position xv is the input (no spool), limited to ±Xvmax;
    each edge passes Cq √(2/ρ) π Fr Sd (Xap0 ± xv) Δp/(Δp² + plam²)^(1/4). A valve whose Xat0 is not its Xap0
    (Hopsan's A-T edge opens as Xap0 - xv all the same) is refused."""
    v = _value
    params = {"Xap0#Value": v("0.0002"), "Xat0#Value": v("0.0002"), "Xvmax#Value": v("0.001"), "plam#Value": v("2e5"),
              "Frap#Value": v("0.5")}
    components = [
        ("HydraulicValve33", "V", params),
        ("HydraulicPressureSourceC", "SP", {"p#Value": v("1e7", "Pa")}),
        ("HydraulicPressureSourceC", "ST", {"p#Value": v("1e5", "Pa")}),
        ("HydraulicPressureSourceC", "SA", {"p#Value": v("4e5", "Pa")}),
        ("SignalRamp", "Ramp", {"y_0#Value": v("0"), "y_A#Value": v("0.004"), "t_start#Value": v("0"),
                                "t_end#Value": v("1")}),
    ]
    connections = [("V.Pp", "SP.P1"), ("V.Pt", "ST.P1"), ("V.Pa", "SA.P1"), ("Ramp.out", "V.xv")]
    path = tmp_path / "v33.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    r = read_hopsan(path).simulate(t_eval=[0.0, 0.1, 0.5])
    ks = 0.67 * np.sqrt(2.0 / 870.0) * np.pi * 0.01

    def g(dp: float) -> float:
        return dp / (dp * dp + 2e5**2) ** 0.25

    x = np.array([0.0, 0.0004, 0.001])  # the ramp's 4 mm/s, limited to Xvmax
    q_pa = ks * 0.5 * (0.0002 + x) * g(1e7 - 4e5)
    q_at = ks * np.clip(0.0002 - x, 0.0, None) * g(4e5 - 1e5)
    np.testing.assert_allclose(r["V.Pp.Flow"], -q_pa, rtol=1e-9)
    np.testing.assert_allclose(r["V.Pa.Flow"], q_pa - q_at, rtol=1e-9)
    np.testing.assert_allclose(r["V.Pt.Flow"], q_at, rtol=1e-9, atol=1e-15)
    path.write_text(_hmf([(k, n, {**p, "Xat0#Value": v("0")} if k == "HydraulicValve33" else p)
                          for k, n, p in components], connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"V \(HydraulicValve33\): Xat0 = 0 m differs from Xap0"):
        read_hopsan(path)


def test_hopsans_pressure_control_valve33_balances_its_pilot_against_spring_and_flow_forces(tmp_path: Path) -> None:
    """[Hopsan2026] Valves/HydraulicPressureControlValve33.hpp at rest: Av (p4 - pref) = (ks + k_f) xv with
    Av = π Sd²/4, k_f = 2 Cq π Sd Fr cos φ |Δp| of P-A while it is open (xv > -Xap0) and of A-T only below
    xv = -Xat0 (Hopsan's switch); the flows Cq √(2/ρ) π Fr Sd (Xap0 ± xv) Δp/(Δp² + plam²)^(1/4). A pilot above
    pref opens P-A further, below it A-T; within Xat0 below 0 both edges flow (their underlaps) but only P-A's
    flow force acts. A spool range that would open A-T past its limit is refused."""
    v = _value
    ps, pt, pa = 2e7, 1e5, 1e7
    sd, fr, phi, ks, cq, plam, x0 = 0.003, 0.1, 1.0, 3e4, 0.67, 1e4, 1e-5
    area = np.pi * sd * sd / 4.0
    ks_root = cq * np.sqrt(2.0 / 870.0) * np.pi * fr * sd

    def g(dp: float) -> float:
        return dp / (dp * dp + plam**2) ** 0.25

    def kf(dp: float) -> float:
        return 2.0 * cq * np.pi * sd * fr * np.cos(phi) * abs(dp)

    x_up = area * 1e5 / (ks + kf(ps - pa))  # pilot 1 bar above pref: P-A open, its flow force
    x_in = -area * 2e3 / (ks + kf(ps - pa))  # 0.02 bar below: both edges open, A-T without its flow force
    x_down = -area * 3e5 / (ks + kf(pa - pt))  # 3 bar below: A-T's flow force too (P-A closed)
    assert x_up > 0 and -x0 < x_in < 0 and x_down < -x0
    for px, x in ((1.01e7, x_up), (1e7 - 2e3, x_in), (0.97e7, x_down)):
        params = {"pref#Value": v("1e7"), "Sd#Value": v(repr(sd)), "Frap#Value": v(repr(fr)), "Frat#Value": v(repr(fr)),
                  "Xap0#Value": v(repr(x0)), "Xat0#Value": v(repr(x0)), "phi#Value": v(repr(phi)), "ks#Value": v(repr(ks)),
                  "Bv#Value": v("1"), "Xvmin#Value": v("-0.003"), "Xvmax#Value": v("0.003")}
        components = [
            ("HydraulicPressureControlValve33", "V", params),
            *[("HydraulicPressureSourceC", f"S{k}", {"p#Value": v(repr(p), "Pa")})
              for k, p in (("1", ps), ("2", pt), ("3", pa), ("4", px))],
        ]
        connections = [(f"V.P{k}", f"S{k}.P1") for k in "1234"]
        path = tmp_path / "pcv.hmf"
        path.write_text(_hmf(components, connections), encoding="utf-8")
        r = read_hopsan(path).simulate(t_eval=[0.0, 0.01], accuracy=1e-9)
        assert float(r["V.xv.Value"][-1]) == pytest.approx(x, rel=1e-4), px
        q_pa = ks_root * max(x0 + x, 0.0) * g(ps - pa)
        q_at = ks_root * max(x0 - x, 0.0) * g(pa - pt)
        assert float(r["V.P3.Flow"][-1]) == pytest.approx(q_pa - q_at, rel=1e-4), px
        assert float(r["V.P4.Flow"][-1]) == 0.0
    params["Xvmin#Value"] = v("-0.004")
    path.write_text(_hmf([("HydraulicPressureControlValve33", "V", params)], []), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"V \(HydraulicPressureControlValve33\): Xvmin = -0.004 m lets A-T open"):
        read_hopsan(path)


def test_hopsans_q_type_piston_with_load_settles_on_its_spring_and_holds_by_its_dry_friction(tmp_path: Path) -> None:
    """[Hopsan2026] Special/HydraulicPistonMkload.hpp between two pressure sources (absolute pressures), a force
    source pressing its port Pmp: at rest kL x = A1 p1 - A2 p2 - F, its flows the leakage Cip (p1 - p2) (Hopsan's
    flow at P1 out of the piston, -Cip (p1 - p2)); with the dry friction fc above that imbalance it does not move;
    its position limited to [xmin, xmax]. A piston area of 0 is refused."""
    v = _value

    def run(params: dict, p1: float, p2: float, force: float) -> dict:
        components = [
            ("HydraulicPistonMkload", "P", params),
            ("HydraulicPressureSourceC", "S1", {"p#Value": v(repr(p1), "Pa")}),
            ("HydraulicPressureSourceC", "S2", {"p#Value": v(repr(p2), "Pa")}),
            ("MechanicForceTransformer", "F", {"F#Value": v(repr(force), "N")}),
        ]
        path = tmp_path / "piston.hmf"
        path.write_text(_hmf(components, [("P.P1", "S1.P1"), ("P.P2", "S2.P1"), ("P.Pmp", "F.P1")]), encoding="utf-8")
        return read_hopsan(path).simulate(t_eval=[0.0, 0.2, 3.0], accuracy=1e-9)

    base = {"A1#Value": v("2e-4"), "A2#Value": v("1e-4"), "Cip#Value": v("1e-12"), "bp#Value": v("100"),
            "mL#Value": v("1"), "bL#Value": v("100"), "kL#Value": v("1e5"), "fc#Value": v("0"),
            "xmin#Value": v("-0.1"), "xmax#Value": v("0.1")}
    r = run(base, 2e6, 3e6, 50.0)
    x = (2e-4 * 2e6 - 1e-4 * 3e6 - 50.0) / 1e5
    assert float(r["P.Pmp.Position"][-1]) == pytest.approx(x, rel=1e-6)
    assert float(r["P.P1.Flow"][-1]) == pytest.approx(-1e-12 * (2e6 - 3e6), rel=1e-5)
    assert float(r["P.P2.Flow"][-1]) == pytest.approx(1e-12 * (2e6 - 3e6), rel=1e-5)
    # 100 N against 60 N of dry friction, overdamped: it moves until the spring takes the other 40 N (then creeps
    # on at the regularisation's pace, v_reg atanh(F/fc): 3 % of the way in the next second)
    r = run({**base, "fc#Value": v("60"), "bL#Value": v("5000")}, 2e6, 3e6, 0.0)
    assert float(r["P.Pmp.Position"][1]) == pytest.approx((100.0 - 60.0) / 1e5, rel=0.03)
    r = run({**base, "fc#Value": v("150")}, 2e6, 3e6, 0.0)  # 100 N below the friction: held (1e-3 m without it)
    assert abs(float(r["P.Pmp.Position"][-1])) < 3e-5
    r = run({**base, "xmax#Value": v("0.0005")}, 2e6, 3e6, 50.0)  # its stroke limited
    assert float(r["P.Pmp.Position"][-1]) == pytest.approx(0.0005, abs=1e-7)
    with pytest.raises(ModelFileError, match=r"P \(HydraulicPistonMkload\): A1 = 0; only a value above 0"):
        run({**base, "A1#Value": v("0")}, 2e6, 3e6, 0.0)


def test_hopsans_pressure_compensating_valve_throttles_as_its_open_pilot_passes_the_close_pilot_by_pref(
    tmp_path: Path,
) -> None:
    """[Hopsan2026] PressureControlValves/HydraulicPressureCompensatingValve.hpp at rest: x0 = X0max -
    (p_open - pref - p_close)/(C_s + C_f (p1 - p2)) within [0, X0max] (X0max = q_nom/√7 MPa, C_s = √p_nom/k_cs,
    C_f = 1/(k_cf √p_nom)), the flow x0 √(p1 - p2); open at the start; its xv logged. A negative hysteresis is
    refused."""
    v = _value
    x_max = 1e-3 / np.sqrt(7e6)
    cs, cf = np.sqrt(7e6) / 1e-8, 1.0 / (1e-8 * np.sqrt(7e6))
    p1, p2, p_close = 1e7, 4e6, 5e6
    for p_open in (6.5e6, 7.1e6, 9e6):  # below pref above P_CLOSE: open; 1 bar over: throttling; far over: shut
        components = [
            ("HydraulicPressureCompensatingValve", "V", {"p_ref#Value": v("2e6"), "p_h#Value": v("0")}),
            *[("HydraulicPressureSourceC", f"S{k}", {"p#Value": v(repr(p), "Pa")})
              for k, p in (("1", p1), ("2", p2), ("O", p_open), ("C", p_close))],
        ]
        connections = [("V.P1", "S1.P1"), ("V.P2", "S2.P1"), ("V.P_OPEN", "SO.P1"), ("V.P_CLOSE", "SC.P1")]
        path = tmp_path / "comp.hmf"
        path.write_text(_hmf(components, connections), encoding="utf-8")
        r = read_hopsan(path).simulate(t_eval=[0.0, 0.3], accuracy=1e-8)
        x0 = min(max(x_max - (p_open - 2e6 - p_close) / (cs + cf * (p1 - p2)), 0.0), x_max)
        assert float(r["V.xv.Value"][0]) == pytest.approx(x_max)
        assert float(r["V.xv.Value"][-1]) == pytest.approx(x0, rel=1e-6, abs=1e-15), p_open
        dp = p1 - p2
        assert float(r["V.P2.Flow"][-1]) == pytest.approx(x0 * dp / (dp * dp + 1e6) ** 0.25, rel=1e-6, abs=1e-15)
    components[0] = ("HydraulicPressureCompensatingValve", "V", {"p_h#Value": v("-1")})
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"V \(HydraulicPressureCompensatingValve\): hysteresis p_h = -1 Pa"):
        read_hopsan(path)


def test_valves_hopsan_has_that_hydroservo_cannot_follow_are_refused(tmp_path: Path) -> None:
    """A one-sided spool that would overshoot (delta_h < 1) and a 4/2 valve with unequal edges are refused,
    each named."""
    v = _value
    _, a, ca = _valve_circuit("Hydraulic22Valve", {"PP": 1e7, "PA": 1e5}, {"delta_h": v("0.7")}, "0.001")
    _, b, cb = _valve_circuit("Hydraulic42Valve2", {"PP": 1e7, "PT": 1e5, "PA": 1e5, "PB": 1e5},
                              {"f_pb#Value": v("0.5")}, None)
    b = [(k, n.replace("V", "W") if n == "V" else f"W{n}", p) for k, n, p in b]
    cb = [(x.replace("V.", "W.").replace("S", "WS"), y.replace("S", "WS")) for x, y in cb]
    path = tmp_path / "refused.hmf"
    path.write_text(_hmf(a + b, ca + cb), encoding="utf-8")
    with pytest.raises(ModelFileError) as err:
        read_hopsan(path)
    text = str(err.value)
    assert "V (Hydraulic22Valve): delta_h = 0.7 < 1" in text
    assert "W (Hydraulic42Valve2): the edges' area fractions f_pa, f_pb, f_at, f_bt differ (1, 0.5, 1, 1)" in text


def test_hopsans_check_valve_passes_k_s_root_dp_one_way(tmp_path: Path) -> None:
    """[Hopsan2026] Restrictors/HydraulicCheckValve.hpp: q = K_s √(p_1 - p_2) while p_1 > p_2, none the other way
    (P2's pressure swept by a ramp from 5 bar below P1's to 5 bar above)."""
    from hydroservo.laws.orifice import transition_pressure

    v = _value
    components = [
        ("HydraulicCheckValve", "CV", {"K_s#Value": v("2e-8")}),
        ("HydraulicPressureSourceC", "S1", {"p#Value": v("1e6", "Pa")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("0", "Pa")}),
        ("SignalRamp", "Ramp", {"y_0#Value": v("5e5"), "y_A#Value": v("1e6"), "t_start#Value": v("0"),
                                "t_end#Value": v("1")}),
    ]
    connections = [("CV.P1", "S1.P1"), ("CV.P2", "S2.P1"), ("Ramp.out", "S2.p")]
    path = tmp_path / "cv.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    comp = imp.system["CV"]
    assert comp.option("opening") == "seat"
    t = np.array([0.0, 0.25, 0.49, 0.75, 1.0])
    r = imp.system.simulate(t_eval=t)
    dp = 1e6 - (5e5 + 1e6 * t)
    p_tr = transition_pressure(float(comp.values["d"]), 870.0, 32e-6, 10.0)
    expected = np.where(dp > 0, 2e-8 * dp / (dp * dp + p_tr * p_tr) ** 0.25, 0.0)
    np.testing.assert_allclose(r["CV.P2.Flow"], expected, rtol=1e-9, atol=1e-15)
    assert p_tr < 100.0  # Pa: turbulent down to some 50 Pa (Hopsan: to the null)


def test_hopsans_g_pressure_valves_settle_on_their_spools_force_balance(tmp_path: Path) -> None:
    """[Hopsan2026] Special/HydraulicPressureReliefValveG.hpp and HydraulicPressureReducingValveG.hpp: at rest the
    spool sits where A_v Δp_over = (ks + 2 Cq w cos φ (p_1 - p_2)) x_v (relief: Δp_over = p_1 - p_2 - pref,
    reducing: pref - p_2, absolute), and passes Cq w x_v √(2/ρ) signedSquareL(p_1 - p_2, p0), w = π Dv frac sin φ;
    its xv is logged. A stream angle outside (0, π/2) is refused."""
    v = _value
    components = [
        ("HydraulicPressureReliefValveG", "RV", {"pref#Value": v("1e7", "Pa")}),
        ("HydraulicPressureReducingValveG", "RD", {"pref#Value": v("2e6", "Pa"), "p0#Value": v("3e5", "Pa")}),
        ("HydraulicPressureSourceC", "S1", {"p#Value": v("1.05e7", "Pa")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("1e5", "Pa")}),
        ("HydraulicPressureSourceC", "S3", {"p#Value": v("1e7", "Pa")}),
        ("HydraulicPressureSourceC", "S4", {"p#Value": v("1.5e6", "Pa")}),
    ]
    connections = [("RV.P1", "S1.P1"), ("RV.P2", "S2.P1"), ("RD.P1", "S3.P1"), ("RD.P2", "S4.P1")]
    path = tmp_path / "g.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["RV"].option("spool") == "balance" and imp.system["RV"].option("pilot") == "drop"
    r = imp.system.simulate(t_eval=[0.0, 1.0], accuracy=1e-8)
    w = np.pi * 0.01 * 0.1 * np.sin(1.17)
    area = np.pi * 0.01**2 / 4.0
    for name, p1, p2, over, p0 in (("RV", 1.05e7, 1e5, 1.05e7 - 1e5 - 1e7, 1e5), ("RD", 1e7, 1.5e6, 2e6 - 1.5e6, 3e5)):
        dp = p1 - p2
        x = area * over / (1e4 + 2.0 * 0.67 * w * np.cos(1.17) * dp)
        assert 0.0 < x < 0.002  # within the stroke
        q = 0.67 * w * x * np.sqrt(2.0 / 870.0) * dp / (dp * dp + p0 * p0) ** 0.25
        assert r[f"{name}.xv.Value"][-1] == pytest.approx(x, rel=1e-6)
        assert r[f"{name}.P2.Flow"][-1] == pytest.approx(q, rel=1e-6)
        assert r[f"{name}.xv.Value"][0] == 0.0  # from Hopsan's start value
    path.write_text(_hmf([(k, n, {**p, "phi#Value": v("2")} if n == "RV" else p) for k, n, p in components],
                         connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"RV \(HydraulicPressureReliefValveG\): stream angle phi = 2 rad"):
        read_hopsan(path)


def test_hopsans_g_pressure_control_and_compensating_valves_balance_their_spools_on_pilot_ports(tmp_path: Path) -> None:
    """[Hopsan2026] Special/HydraulicPressureControlValveG.hpp (Δp_over = p3 - p4 - pref) and
    HydraulicPressureCompensatingValveG.hpp (Δp_over = pref + p3 - p2): at rest A_v Δp_over = (ks + 2 Cq w cos φ
    (p1 - p2)) x_v, the flow Cq w x_v √(2/ρ) signedSquareL(p1 - p2, p0), w = π Dv frac sin φ; the pilots take no
    flow."""
    v = _value
    components = [
        ("HydraulicPressureControlValveG", "CV", {"pref#Value": v("1e6")}),
        ("HydraulicPressureCompensatingValveG", "PC", {"pref#Value": v("1e6"), "Dv#Value": v("0.01"),
                                                       "Xvmax#Value": v("0.002")}),
        *[("HydraulicPressureSourceC", k, {"p#Value": v(repr(p), "Pa")})
          for k, p in (("S1", 1e7), ("S2", 2e6), ("S3", 5.2e6), ("S4", 4e6), ("T1", 1e7), ("T2", 5.1e6),
                       ("T3", 4.3e6))],
    ]
    connections = [("CV.P1", "S1.P1"), ("CV.P2", "S2.P1"), ("CV.P3", "S3.P1"), ("CV.P4", "S4.P1"),
                   ("PC.P1", "T1.P1"), ("PC.P2", "T2.P1"), ("PC.P3", "T3.P1")]
    path = tmp_path / "gp.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["CV"].option("pilot") == "ports" and imp.system["PC"].option("pilot") == "port"
    r = imp.system.simulate(t_eval=[0.0, 1.0], accuracy=1e-8)
    w = np.pi * 0.01 * 0.1 * np.sin(1.17)
    area = np.pi * 0.01**2 / 4.0
    for name, p1, p2, over in (("CV", 1e7, 2e6, 5.2e6 - 4e6 - 1e6), ("PC", 1e7, 5.1e6, 1e6 + 4.3e6 - 5.1e6)):
        dp = p1 - p2
        x = area * over / (1e4 + 2.0 * 0.67 * w * np.cos(1.17) * dp)
        assert 0.0 < x < 0.002  # within the stroke
        q = 0.67 * w * x * np.sqrt(2.0 / 870.0) * dp / (dp * dp + 1e10) ** 0.25
        assert r[f"{name}.xv.Value"][-1] == pytest.approx(x, rel=1e-6)
        assert r[f"{name}.P2.Flow"][-1] == pytest.approx(q, rel=1e-6)
        assert r[f"{name}.P3.Flow"][-1] == 0.0


def test_hopsans_pressure_controlled_valves_open_their_edges_as_the_pilot_pressure_sets_the_spool(tmp_path: Path) -> None:
    """[Hopsan2026] PressureControlled/HydraulicPressureControlled22Valve.hpp, ...22Valve2, ...42Valve3: at rest the
    spool sits at x_vmax·limit((p_C - Fs_min)/(Fs_max - Fs_min), 0, 1) (p_C absolute); the default-closed 2/2 valve
    opens PP-PA as x_v, the default-open one as x_vmax - x_v, the 4/2 valve 3 P-A and B-T as x_vmax - x_v and P-B,
    A-T as x_v, each Cq f π d √(2/ρ) times the opening times √Δp. Fs_max not above Fs_min is refused."""
    from hydroservo.laws.orifice import transition_pressure

    v = _value
    sources = {"SP": 2e7, "ST": 1e5, "SA": 1.2e7, "SB": 0.8e7, "SC": 3.25e5, "SD": 7.75e5}
    components = [
        ("HydraulicPressureControlled22Valve", "V1", {}),
        ("HydraulicPressureControlled22Valve2", "V2", {}),
        ("HydraulicPressureControlled42Valve3", "V3", {"x_vmax#Value": v("0.002")}),
        *[("HydraulicPressureSourceC", k, {"p#Value": v(repr(p), "Pa")}) for k, p in sources.items()],
    ]
    connections = [("V1.PP", "SP.P1"), ("V1.PA", "SA.P1"), ("V1.PC", "SC.P1"),
                   ("V2.PP", "SP.P1"), ("V2.PA", "SA.P1"), ("V2.PC", "SC.P1"),
                   ("V3.PP", "SP.P1"), ("V3.PT", "ST.P1"), ("V3.PA", "SA.P1"), ("V3.PB", "SB.P1"), ("V3.PC", "SD.P1")]
    path = tmp_path / "pc.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    r = read_hopsan(path).simulate(t_eval=[0.0, 1.0], accuracy=1e-8)
    p_tr = transition_pressure(1e-3, 870.0, 32e-6, 10.0)
    kc = 0.67 * np.pi * 0.01 * np.sqrt(2.0 / 870.0)

    def q(opening: float, dp: float) -> float:
        return kc * opening * dp / (dp * dp + p_tr * p_tr) ** 0.25

    x1 = 0.01 * (3.25e5 - 1e5) / 9e5  # a quarter of the stroke
    x3 = 0.002 * 0.75
    assert r["V1.x_v.Value"][-1] == pytest.approx(x1, rel=1e-6) and r["V2.x_v.Value"][-1] == pytest.approx(x1)
    assert r["V3.x_v.Value"][-1] == pytest.approx(x3, rel=1e-6)
    assert r["V1.x_v.Value"][0] == 0.0  # Hopsan's spool starts at 0 whatever the pilot
    # three valves share the node SA: its flow is logged by none of them; their own flows PP to PA
    assert r["V1.Q"][-1] == pytest.approx(q(x1, 0.8e7), rel=1e-6)
    assert r["V2.Q"][-1] == pytest.approx(q(0.01 - x1, 0.8e7), rel=1e-6)
    q_pa, q_pb = q(0.002 - x3, 2e7 - 1.2e7), q(x3, 2e7 - 0.8e7)
    q_at, q_bt = q(x3, 1.2e7 - 1e5), q(0.002 - x3, 0.8e7 - 1e5)
    assert r["V3.QB"][-1] == pytest.approx(q_pa - q_at, rel=1e-6)  # Hopsan's PA is the FourWayValve's B
    assert r["V3.PB.Flow"][-1] == pytest.approx(q_pb - q_bt, rel=1e-6)
    assert r["V3.PT.Flow"][-1] == pytest.approx(q_at + q_bt, rel=1e-6)
    path.write_text(_hmf([(k, n, {"Fs_max#Value": v("1e5")} if n == "V1" else p) for k, n, p in components],
                         connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"V1 \(HydraulicPressureControlled22Valve\): Fs_max = 100000 Pa is not"):
        read_hopsan(path)


def test_hopsans_gas_accumulator_charges_through_its_inlet_coefficient(tmp_path: Path) -> None:
    """[Hopsan2026] Volumes&Lines/HydraulicAckumulator.hpp: q = V0 ẋ = Kca (p_1 - pa), pa = p0/(1 - x)^kappa
    (absolute), from the start value xmp; its outputs pa, Va = V0 (1 - x), xmp and vmp = ẋ are logged. A
    polytropic exponent outside [1, 1.67] is refused."""
    v = _value
    components = [
        ("HydraulicAckumulator", "Acc", {"V0#Value": v("0.002"), "Kca#Value": v("2e-9"), "kappa#Value": v("1.3"),
                                         "p0#Value": v("8e6"), "xmp#Value": v("0.2")}),
        ("HydraulicPressureSourceC", "S", {"p#Value": v("1.5e7", "Pa")}),
    ]
    path = tmp_path / "acc.hmf"
    path.write_text(_hmf(components, [("Acc.P1", "S.P1")]), encoding="utf-8")
    r = read_hopsan(path).simulate(t_eval=[0.0, 1.0], accuracy=1e-9)
    pa = 8e6 / 0.8**1.3
    assert r["Acc.pa.Value"][0] == pytest.approx(pa, rel=1e-9)
    assert r["Acc.xmp.Value"][0] == pytest.approx(0.2) and r["Acc.Va.Value"][0] == pytest.approx(0.0016)
    assert r["Acc.vmp.Value"][0] == pytest.approx(2e-9 * (1.5e7 - pa) / 0.002, rel=1e-9)
    x_end = 1.0 - (8e6 / 1.5e7) ** (1 / 1.3)  # charged until pa reaches the source's pressure
    assert r["Acc.xmp.Value"][-1] == pytest.approx(x_end, rel=1e-5)
    assert (r.units["Acc.xmp.Value"], r.units["Acc.vmp.Value"]) == ("", "1/s")  # a state of charge and its rate
    components[0][2]["kappa#Value"] = v("2")
    path.write_text(_hmf(components, [("Acc.P1", "S.P1")]), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"Acc \(HydraulicAckumulator\): kappa = 2"):
        read_hopsan(path)


def test_hopsans_piston_accumulator_settles_where_its_gas_takes_the_source_pressure(tmp_path: Path) -> None:
    """[Hopsan2026] Volumes&Lines/HydraulicPistonAckumulator.hpp: ML ẍ = Ap (p_1 - pa) - Bp ẋ, pa =
    p0 (SL/(SL - x))^kappa (absolute), q = Ap ẋ: from xmp at rest it accelerates at Ap (p_1 - pa)/ML and settles
    where pa = p_1; its outputs pa, Va = Ap (SL - x), xmp and vmp are logged."""
    v = _value
    components = [
        ("HydraulicPistonAckumulator", "Acc", {"Ap#Value": v("0.002"), "SL#Value": v("0.4"), "Bp#Value": v("400"),
                                               "ML#Value": v("3"), "kappa#Value": v("1.3"), "p0#Value": v("8e6"),
                                               "xmp#Value": v("0.1")}),
        ("HydraulicPressureSourceC", "S", {"p#Value": v("1.5e7", "Pa")}),
    ]
    path = tmp_path / "pacc.hmf"
    path.write_text(_hmf(components, [("Acc.P1", "S.P1")]), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["Acc"].option("inlet") == "piston"
    r = imp.system.simulate(t_eval=[0.0, 3.0], accuracy=1e-8)
    pa = 8e6 * (0.4 / 0.3) ** 1.3
    assert r["Acc.pa.Value"][0] == pytest.approx(pa, rel=1e-9)
    assert r["Acc.xmp.Value"][0] == pytest.approx(0.1) and r["Acc.Va.Value"][0] == pytest.approx(0.002 * 0.3)
    assert r["Acc.vmp.Value"][0] == 0.0
    assert imp.system["Acc"].state_equations(  # the acceleration at the start
        0.0, {"x_p": 0.1, "v_p": 0.0}, {"pP": 1.5e7 - 101325.0}, imp.system["Acc"].values,
        {"p": pa - 101325.0},
    )["v_p"] == pytest.approx(0.002 * (1.5e7 - pa) / 3.0, rel=1e-9)
    x_end = 0.4 * (1.0 - (8e6 / 1.5e7) ** (1 / 1.3))
    assert r["Acc.xmp.Value"][-1] == pytest.approx(x_end, rel=1e-5)
    assert r["Acc.pa.Value"][-1] == pytest.approx(1.5e7, rel=1e-6)
    assert (r.units["Acc.xmp.Value"], r.units["Acc.vmp.Value"]) == ("m", "m/s")  # the piston's position, speed


def test_math_blocks_rate_limiter_and_dead_zone_map_with_hopsans_ports(tmp_path: Path) -> None:
    """Hopsan's math blocks become one Function each, with the option naming the function, their ``error``
    output where Hopsan's has one and atan2's inputs inY and inX (an unconnected inX takes its start value);
    SignalSquare and SignalSign too. The rate limiter keeps c_up and c_down; the dead zone u_dstart and u_dend."""
    v = _value
    ramp = {"y_0#Value": v("-2"), "y_A#Value": v("4"), "t_start#Value": v("0"), "t_end#Value": v("4")}
    components = [
        ("SignalRamp", "Ramp", ramp),
        ("SignalSqrt", "Sqrt", {}),
        ("SignalAcos", "Acos", {}),
        ("SignalAtan2", "Atan2", {"inX#Value": v("-1")}),
        ("SignalSquare", "Square", {}),
        ("SignalSign", "Sign", {}),
        ("SignalCosh", "Cosh", {}),
        ("SignalDeadZone", "DZ", {"u_dstart#Value": v("-0.5"), "u_dend#Value": v("1")}),
        ("SignalRateLimiter", "RL", {"c_up#Value": v("0.5"), "c_down#Value": v("-2"), "in#Value": v("-2")}),
        ("SignalSink", "Scope", {}),
    ]
    connections = [("Ramp.out", f"{b}.in") for b in ("Sqrt", "Acos", "Square", "Sign", "Cosh", "DZ", "RL")]
    connections += [("Ramp.out", "Atan2.inY"), ("Sqrt.error", "Scope.in")]
    path = tmp_path / "math.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    kinds = {hopsan: became for hopsan, _, became in imp.mapping}
    assert kinds["Sqrt"] == "Function Sqrt" and kinds["RL"] == "RateLimiter RL" and kinds["DZ"] == "DeadZone DZ"
    system = imp.system
    assert system["Atan2"].option("function") == "atan2" and system["Sign"].option("function") == "sign"
    assert system["RL"].values["c_up"] == 0.5 and system["RL"].values["c_down"] == -2.0
    assert system.plots == [["Sqrt.error.Value"]]
    t = np.array([0.0, 0.5, 1.0, 1.5, 2.5, 3.0, 3.5])
    u = t - 2.0
    r = system.simulate(t_eval=t, accuracy=1e-8)
    np.testing.assert_allclose(r["Sqrt.out.Value"], np.sqrt(np.clip(u, 0, None)), atol=1e-12)
    np.testing.assert_allclose(r["Sqrt.error.Value"], (u < 0).astype(float))
    np.testing.assert_allclose(r["Acos.out.Value"], np.arccos(np.clip(u, -1, 1)), atol=1e-12)
    np.testing.assert_allclose(r["Acos.error.Value"], (np.abs(u) > 1).astype(float))
    np.testing.assert_allclose(r["Atan2.out.Value"], np.arctan2(u, -1.0), atol=1e-12)
    np.testing.assert_allclose(r["Square.out.Value"], u * u, atol=1e-12)
    np.testing.assert_allclose(r["Sign.out.Value"], np.where(u >= 0, 1.0, -1.0))
    np.testing.assert_allclose(r["Cosh.out.Value"], np.cosh(u), atol=1e-12)
    np.testing.assert_allclose(r["DZ.out.Value"], np.where(u < -0.5, u + 0.5, np.where(u > 1, u - 1, 0.0)), atol=1e-12)
    # from -2 (its input's start) the limiter rises at 0.5/s behind the ramp of 1/s
    np.testing.assert_allclose(r["RL.out.Value"], -2.0 + 0.5 * t, atol=1e-5)


def _lookup_model(folder: Path, **table: tuple[str, str]) -> Path:
    """A ramp from -1 to 5 over 6 s through a Signal1DLookupTable with the parameters ``table``."""
    v = _value
    ramp = {"y_0#Value": v("-1"), "y_A#Value": v("6"), "t_start#Value": v("0"), "t_end#Value": v("6")}
    components = [("SignalRamp", "Ramp", ramp), ("Signal1DLookupTable", "LUT", table)]
    text = _hmf(components, [("Ramp.out", "LUT.in")])
    for name in ("filename", "csvsep", "comment", "text"):  # Hopsan's text parameters
        text = text.replace(f'type="double" name="{name}"', f'type="string" name="{name}"')
    path = folder / "lookup.hmf"
    path.write_text(text, encoding="utf-8")
    return path


def test_hopsans_lookup_table_reads_its_csv_beside_the_model_and_interpolates_its_input(tmp_path: Path) -> None:
    """Signal1DLookupTable: the CSV named relative to the model, read with its separator, lines to skip,
    comment character and columns (inid, outid); linear between the breakpoints, held outside them, as
    Hopsan's LookupTable1D."""
    (tmp_path / "tables").mkdir()
    (tmp_path / "tables" / "f.csv").write_text("made by hand\n# y;x\n9;3\n1;0\n3;1\n", encoding="utf-8")
    v = _value
    path = _lookup_model(tmp_path, filename=v("tables/f.csv"), csvsep=v(";"), numlineskip=v("1"), comment=v("#"),
                         inid=v("1"), outid=v("0"))
    imp = import_hopsan(path)
    table = imp.system["LUT"]
    assert table.option("index") == "input" and "3 rows of 'tables/f.csv'" in dict(
        (h, b) for h, _, b in imp.mapping)["LUT"]
    t = np.array([0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0])
    r = imp.system.simulate(t_eval=t)
    u = t - 1.0
    np.testing.assert_allclose(r["LUT.out.Value"], np.interp(u, [0.0, 1.0, 3.0], [1.0, 3.0, 9.0]), atol=1e-12)
    assert r["LUT.out.Value"][0] == 1.0 and r["LUT.out.Value"][-1] == 9.0  # held outside, as Hopsan's
    table = import_hopsan(_lookup_model(tmp_path, text=v("0,2&#xa;1,4&#xa;"))).system["LUT"]  # the text instead
    np.testing.assert_array_equal(table.times, [0.0, 1.0])
    np.testing.assert_array_equal(table.table_values, [2.0, 4.0])


def test_hopsans_plo_lookup_table_reads_its_named_columns_beside_the_model(tmp_path: Path) -> None:
    """Signal1DPLOLookupTable: the PLO file named relative to the model, its columns invar and outvar by name (a
    first 'Time' column not counted in the header's number, as Hopsan's PLOParser), rows sorted; linear between
    the breakpoints, held outside; a column that is not there and a file outside the model's folder refused."""
    (tmp_path / "tables").mkdir()
    plo = ("    'VERSION'\n    1\n    'f.plo' 'model' 'today'\n    2    3\n    'Time',    'x',    'y'\n"
           "  Time 1 1\n  0.0 3 9\n  0.1 0 1\n  0.2 1 3\n  DAT model\n")
    (tmp_path / "tables" / "f.plo").write_text(plo, encoding="utf-8")
    v = _value
    ramp = {"y_0#Value": v("-1"), "y_A#Value": v("6"), "t_start#Value": v("0"), "t_end#Value": v("6")}

    def model(**table: tuple[str, str]) -> Path:
        text = _hmf([("SignalRamp", "Ramp", ramp), ("Signal1DPLOLookupTable", "LUT", table)], [("Ramp.out", "LUT.in")])
        for name in ("filename", "invar", "outvar"):
            text = text.replace(f'type="double" name="{name}"', f'type="string" name="{name}"')
        path = tmp_path / "plo.hmf"
        path.write_text(text, encoding="utf-8")
        return path

    imp = import_hopsan(model(filename=v("tables/f.plo"), invar=v("x"), outvar=v("y")))
    assert imp.system["LUT"].option("index") == "input"
    t = np.array([0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0])
    r = imp.system.simulate(t_eval=t)
    np.testing.assert_allclose(r["LUT.out.Value"], np.interp(t - 1.0, [0.0, 1.0, 3.0], [1.0, 3.0, 9.0]), atol=1e-12)
    with pytest.raises(ModelFileError, match="no column 'z'; its columns: Time, x, y"):
        import_hopsan(model(filename=v("tables/f.plo"), invar=v("x"), outvar=v("z")))
    with pytest.raises(ModelFileError, match="outside the model file's folder"):
        import_hopsan(model(filename=v("../f.plo"), invar=v("x"), outvar=v("y")))


def test_hopsans_2d_lookup_table_is_bilinear_held_at_its_edges_and_round_trips(tmp_path: Path) -> None:
    """Signal2DLookupTable: the CSV beside the model (row, col, value per line, row-major; the last line nR, nC),
    bilinear in row and col as Hopsan's LookupTable2D (along row in the two columns about col, then along col),
    held at the edges; written to a model file and read back; numlineskip (which Hopsan ignores) and breakpoints
    listed out of order (which Hopsan sorts without their values) refused."""
    (tmp_path / "m.csv").write_text("# row,col,value\n0,0,1\n0,4,2\n0,5,6\n2,0,7\n2,4,9\n2,5,3\n2,3,0\n",
                                    encoding="utf-8")
    v = _value
    components = [
        ("SignalRamp", "R", {"y_0#Value": v("-1"), "y_A#Value": v("4"), "t_start#Value": v("0"), "t_end#Value": v("4")}),
        ("SignalSineWave", "C", {"y_A#Value": v("3"), "f#Value": v("0.25")}),
        ("Signal2DLookupTable", "LUT", {"filename": v("m.csv"), "comment": v("#")}),
    ]

    def model(**extra: tuple[str, str]) -> Path:
        table = [(k, n, {**p, **extra} if n == "LUT" else p) for k, n, p in components]
        text = _hmf(table, [("R.out", "LUT.row"), ("C.out", "LUT.col")])
        for name in ("filename", "comment"):
            text = text.replace(f'type="double" name="{name}"', f'type="string" name="{name}"')
        path = tmp_path / "lut2.hmf"
        path.write_text(text, encoding="utf-8")
        return path

    imp = import_hopsan(model())
    lut = imp.system["LUT"]
    np.testing.assert_array_equal(lut.rows, [0.0, 2.0])
    np.testing.assert_array_equal(lut.table_values, [[1.0, 2.0, 6.0], [7.0, 9.0, 3.0]])
    t = np.linspace(0.0, 4.0, 17)
    r = imp.system.simulate(t_eval=t)
    row = np.clip(t - 1.0, 0.0, 2.0) / 2.0  # the fraction along rows
    col = np.clip(3.0 * np.sin(2 * np.pi * 0.25 * t), 0.0, 5.0)
    left = np.where(col <= 4.0, (1 - row) * 1 + row * 7, (1 - row) * 2 + row * 9)
    right = np.where(col <= 4.0, (1 - row) * 2 + row * 9, (1 - row) * 6 + row * 3)
    w = np.where(col <= 4.0, col / 4.0, col - 4.0)
    np.testing.assert_allclose(r["LUT.out.Value"], (1 - w) * left + w * right, atol=1e-12)
    from hydroservo.io.model_file import load_model
    from hydroservo.workflows.hopsan import ImportHopsan

    files = ImportHopsan(model()).run().write(tmp_path / "out")
    again = load_model(files["model"])
    np.testing.assert_allclose(again.simulate(t_eval=t)["LUT.out.Value"], r["LUT.out.Value"], atol=1e-12)
    with pytest.raises(ModelFileError, match="numlineskip = 1: Hopsan's 2D lookup table never skips lines"):
        import_hopsan(model(numlineskip=v("1")))
    (tmp_path / "m.csv").write_text("2,0,7\n2,4,9\n2,5,3\n0,0,1\n0,4,2\n0,5,6\n2,3,0\n", encoding="utf-8")
    with pytest.raises(ModelFileError, match="the row breakpoints 2, 0: expected them strictly increasing as listed"):
        import_hopsan(model())


def test_a_lookup_table_driven_by_a_constant_reads_its_file_once(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A constant into the table's input is folded (its value looked up); probing the block for its ports reads
    no file: the table's CSV is read once, from the model's folder."""
    import hydroservo.io.tables as tables

    (tmp_path / "f.csv").write_text("0,1\n2,5\n", encoding="utf-8")
    calls = []
    real = tables.read_lookup_table
    monkeypatch.setattr(tables, "read_lookup_table", lambda *a, **k: calls.append(a[0]) or real(*a, **k))
    v = _value
    components = [("SignalConstant", "C", {"y#Value": v("1.5")}), ("Signal1DLookupTable", "LUT", {"filename": v("f.csv")})]
    text = _hmf(components, [("C.y", "LUT.in")]).replace('type="double" name="filename"', 'type="string" name="filename"')
    (tmp_path / "m.hmf").write_text(text, encoding="utf-8")
    monkeypatch.chdir(tmp_path.parent)
    r = import_hopsan(tmp_path / "m.hmf").system.simulate(t_eval=[0.0, 1.0])
    np.testing.assert_allclose(r["LUT.out.Value"], 4.0)
    assert calls == [(tmp_path / "f.csv").resolve()]


def test_hopsans_lookup_table_missing_malformed_or_outside_the_model_folder_is_refused(tmp_path: Path) -> None:
    v = _value
    with pytest.raises(ModelFileError, match=r"LUT \(Signal1DLookupTable\): filename: table file .*none\.csv.*cannot read"):
        import_hopsan(_lookup_model(tmp_path, filename=v("none.csv")))
    (tmp_path / "bad.csv").write_text("0,0\n1,one\n", encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"LUT \(Signal1DLookupTable\).*line 2, column 1: 'one' is no finite number"):
        import_hopsan(_lookup_model(tmp_path, filename=v("bad.csv")))
    (tmp_path / "ok.csv").write_text("0,0\n1,1\n", encoding="utf-8")
    inner = tmp_path / "model"
    inner.mkdir()
    for name in ("../ok.csv", str(tmp_path / "ok.csv")):
        with pytest.raises(ModelFileError, match="outside the model file's folder"):
            import_hopsan(_lookup_model(inner, filename=v(name)))
    with pytest.raises(ModelFileError, match="neither a file"):
        import_hopsan(_lookup_model(tmp_path))
    with pytest.raises(ModelFileError, match="out of|column 2"):  # outid beyond the file's columns
        import_hopsan(_lookup_model(tmp_path, filename=v("ok.csv"), outid=v("2")))


def test_hopsans_pid_controllers_map_to_a_pid_with_their_anti_windup(tmp_path: Path) -> None:
    """SignalPID: u = limit(uI + Kp (yref - y) - Kd dy), its integral stopped at the limits (clamping), here
    uI + 2 + 0.5 reaching umax = 3 at 0.5 s; SignalPID2 with 'de' connected: v = K e + I + K Td de = 3 + I,
    I' = K/Ti e + (Umax - v)/Tt above Umax = 3.5, so I = 1 - 0.5 exp(-2 (t - 0.5)) from 0.5 s, the output
    limited to Uoutmax = 3.9; SignalPIlead with its measurement at rest at 0.5 (the lead's output too):
    err = yref - 0.5, u = k1 err + k1 wa integral (k1 = wa/kx); a unit delay passes its input on."""
    v = _value
    components = [
        ("SignalConstant", "One", {"y#Value": v("1")}),
        ("SignalConstant", "Half", {"y#Value": v("0.5")}),
        ("SignalPID", "PID", {"Kp#Value": v("2"), "KI#Value": v("1"), "Kd#Value": v("-1"), "dy#Value": v("0.5"),
                              "umin#Value": v("-3"), "umax#Value": v("3")}),
        ("SignalPID2", "PID2", {"K": v("2"), "Ti": v("2"), "Tt": v("0.5"), "Td": v("1"), "Umax": v("3.5"),
                                "Uoutmax": v("3.9")}),
        ("SignalPIlead", "Lead", {"y#Value": v("0.5"), "wa": v("2"), "kx": v("1"), "da": v("1"), "umax": v("3")}),
        ("SignalUnitDelay", "Delay", {}),
    ]
    connections = [("One.y", "PID.yref"), ("One.y", "PID2.e"), ("Half.y", "PID2.de"), ("One.y", "Lead.yref"),
                   ("PID.u", "Delay.in")]
    path = tmp_path / "pid.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    system = imp.system
    pid, pid2, lead = system["PID"], system["PID2"], system["Lead"]
    assert pid.option("anti_windup") == "clamping" and pid.option("derivative") == "input"
    assert pid.values["Kd"] == 1.0 and pid.values["upper"] == 3.0  # -Kd dy: the input de is dy
    assert pid2.option("anti_windup") == "tracking" and pid2.values["Ki"] == 1.0 and pid2.values["Kd"] == 2.0
    assert pid2.values["track_upper"] == 3.5 and pid2.values["upper"] == 3.9 and pid2.values["T_t"] == 0.5
    assert lead.values["Kp"] == 2.0 and lead.values["Ki"] == 4.0 and lead.option("anti_windup") == "clamping"
    assert system["Lead_lead"].values["a1"] == 1.0 and system["Lead_lead"].values["b1"] == 0.5
    t = np.array([0.0, 0.25, 0.5, 1.0, 1.5, 2.0])
    r = system.simulate(t_eval=t, accuracy=1e-8)
    np.testing.assert_allclose(r["PID.u.Value"], np.minimum(2.5 + t, 3.0), atol=1e-6)
    np.testing.assert_allclose(r["PID.uI.Value"], np.minimum(t, 0.5), atol=1e-6)
    integral = np.where(t < 0.5, t, 1.0 - 0.5 * np.exp(-2.0 * (t - 0.5)))
    np.testing.assert_allclose(r["PID2.u.Value"], np.minimum(3.0 + integral, 3.9), atol=1e-6)
    np.testing.assert_allclose(r["Lead.err.Value"], 0.5, atol=1e-9)
    np.testing.assert_allclose(r["Lead.u.Value"], np.minimum(1.0 + 2.0 * t, 3.0), atol=1e-6)
    np.testing.assert_allclose(r["Delay.out.Value"], r["PID.u.Value"])
    # uI is Ki (or k1 wa) times the integral of the error [s]: a control signal as u is, without unit
    assert system.aliases["PID.uI.Value"].unit == "" and system.aliases["Lead.uI.Value"].unit == ""


def test_pid2_without_its_derivative_and_unit_delays_closing_algebraic_loops_are_refused(tmp_path: Path) -> None:
    v = _value
    path = tmp_path / "pid2.hmf"
    path.write_text(_hmf([("SignalPID2", "PID2", {"Td": v("0.1")})], []), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"PID2 \(SignalPID2\): Td = 0.1 s with 'de' unconnected"):
        import_hopsan(path)
    components = [("SignalStep", "Step", {}), ("SignalSubtract", "Error", {}), ("SignalGain", "Gain", {}),
                  ("SignalUnitDelay", "Delay", {})]
    connections = [("Step.out", "Error.in1"), ("Error.out", "Gain.in"), ("Gain.out", "Delay.in"),
                   ("Delay.out", "Error.in2")]
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"algebraic loop .*unit delays \(Delay: SignalUnitDelay\)"):
        import_hopsan(path)
    components[2] = ("SignalIntegrator2", "Gain", {})  # a state in the loop: imported
    path.write_text(_hmf(components, connections), encoding="utf-8")
    assert import_hopsan(path).system["Delay"].values["K"] == 1.0


def test_a_filter_starts_from_the_value_of_the_signal_driving_it(tmp_path: Path) -> None:
    """Hopsan's filters start from their output's start value with their input at the value it has when the model
    is initialised (FirstOrderTransferFunction::initialize reads the input's node): a high-pass filter behind a
    low-pass filter that starts at 0.3 starts at rest at 0.3, its output 0, not 0.3 (the file's 'in' is 0)."""
    v = _value
    components = [("SignalLP1Filter", "LP", {"out#Value": v("0.3"), "omega": v("6")}),
                  ("SignalHP1Filter", "HP", {"omega": v("100")})]
    path = tmp_path / "filters.hmf"
    path.write_text(_hmf(components, [("LP.out", "HP.in")]), encoding="utf-8")
    system = import_hopsan(path).system
    assert system["HP"].values["y0"] == pytest.approx(-0.3)
    r = system.simulate(t_eval=[0.0, 1e-3])
    assert abs(r["HP.out.Value"][0]) < 1e-12


def test_hopsans_rounding_comparison_logic_blocks_and_latch_map_with_their_ports(tmp_path: Path) -> None:
    """SignalFloor, SignalCeil, SignalRound as Functions; SignalGreaterThan and SignalSmallerThan read in and
    x_limit (unconnected: its start value), SignalAnd and SignalOr in1 and in2; SignalSRlatch's setCond,
    resetCond, Qstate and notQstate, from its start value of Qstate."""
    v = _value
    ramp = {"y_0#Value": v("-2"), "y_A#Value": v("4"), "t_start#Value": v("0"), "t_end#Value": v("4")}
    components = [
        ("SignalRamp", "Ramp", ramp),
        ("SignalFloor", "Floor", {}), ("SignalCeil", "Ceil", {}), ("SignalRound", "Round", {}),
        ("SignalGreaterThan", "GT", {"x_limit#Value": v("0.5")}), ("SignalSmallerThan", "ST", {}),
        ("SignalAnd", "And", {}), ("SignalOr", "Or", {"in2#Value": v("0")}),
        ("SignalSRlatch", "Latch", {"Qstate#Value": v("1")}),
    ]
    connections = [("Ramp.out", f"{b}.in") for b in ("Floor", "Ceil", "Round", "GT", "ST")]
    connections += [("GT.out", "And.in1"), ("ST.out", "And.in2"), ("GT.out", "Or.in1"), ("GT.out", "Latch.resetCond")]
    path = tmp_path / "logic.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    system = import_hopsan(path).system
    assert system["GT"].option("function") == "greater" and system["Latch"].values["Q0"] == 1.0
    t = np.array([0.0, 0.5, 1.8, 2.25, 3.0, 3.9])
    u = t - 2.0
    r = system.simulate(t_eval=t)
    np.testing.assert_array_equal(r["Floor.out.Value"], np.floor(u))
    np.testing.assert_array_equal(r["Ceil.out.Value"], np.ceil(u))
    np.testing.assert_array_equal(r["Round.out.Value"], np.sign(u) * np.floor(np.abs(u) + 0.5))
    np.testing.assert_array_equal(r["GT.out.Value"], (u > 0.5).astype(float))
    np.testing.assert_array_equal(r["ST.out.Value"], (u < 0.0).astype(float))  # x_limit's start value 0
    np.testing.assert_array_equal(r["And.out.Value"], np.zeros_like(u))
    np.testing.assert_array_equal(r["Or.out.Value"], (u > 0.5).astype(float))
    # the latch starts set and is reset once the ramp passes 0.5 (t = 2.5 s)
    np.testing.assert_allclose(r["Latch.Qstate.Value"], (u <= 0.5).astype(float), atol=1e-9)
    np.testing.assert_allclose(r["Latch.notQstate.Value"], (u > 0.5).astype(float), atol=1e-9)


def test_hopsans_max_min_sub_not_and_xor_read_their_ports_and_multiports(tmp_path: Path) -> None:
    """SignalMax and SignalMin: the largest and smallest of the signals joining 'in' (three: chained; one passes
    on; none is 0); SignalSub: sum(insum) - sum(insub) (either may be empty); SignalNot: in <= 0.5; SignalXor:
    in1 > 0.5 or in2 > 0.5, not both. On a ramp u from -2 to 2, its negative and constants 0.5 and 1."""
    v = _value
    ramp = {"y_0#Value": v("-2"), "y_A#Value": v("4"), "t_start#Value": v("0"), "t_end#Value": v("4")}
    components = [
        ("SignalRamp", "Ramp", ramp), ("SignalGain", "Neg", {"k#Value": v("-1")}),
        ("SignalConstant", "A", {"y#Value": v("0.5")}), ("SignalConstant", "B", {"y#Value": v("1")}),
        ("SignalMax", "Max", {}), ("SignalMin", "Min", {}), ("SignalMax", "Max1", {}), ("SignalMin", "Min0", {}),
        ("SignalSub", "Sub", {}), ("SignalSub", "Sub0", {}), ("SignalNot", "Not", {}), ("SignalXor", "Xor", {}),
    ]
    connections = [("Ramp.out", "Neg.in"), ("Ramp.out", "Max.in"), ("Neg.out", "Max.in"), ("A.y", "Max.in"),
                   ("Ramp.out", "Min.in"), ("A.y", "Min.in"), ("Ramp.out", "Max1.in"),
                   ("Ramp.out", "Sub.insum"), ("B.y", "Sub.insum"), ("A.y", "Sub.insub"), ("Neg.out", "Sub.insub"),
                   ("A.y", "Sub0.insub"), ("Ramp.out", "Not.in"), ("Ramp.out", "Xor.in1"), ("Neg.out", "Xor.in2")]
    path = tmp_path / "arith.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    kinds = {hopsan: became for hopsan, _, became in imp.mapping}
    assert kinds["Max"] == "2 Functions (max) chained (Max, ...)" and kinds["Min"] == "Function Min"
    assert kinds["Max1"] == "Gain Max1" and kinds["Min0"] == "Constant Min0" and kinds["Not"] == "Function Not"
    t = np.array([0.0, 0.5, 1.8, 2.25, 3.0, 3.9])
    u = t - 2.0
    r = imp.system.simulate(t_eval=t)
    np.testing.assert_allclose(r["Max.out.Value"], np.maximum(np.abs(u), 0.5), atol=1e-12)
    np.testing.assert_allclose(r["Min.out.Value"], np.minimum(u, 0.5), atol=1e-12)
    np.testing.assert_allclose(r["Max1.out.Value"], u, atol=1e-12)
    np.testing.assert_array_equal(r["Min0.out.Value"], np.zeros_like(u))
    np.testing.assert_allclose(r["Sub.out.Value"], u + 1.0 - 0.5 + u, atol=1e-12)
    np.testing.assert_allclose(r["Sub0.out.Value"], np.full_like(u, -0.5), atol=1e-12)
    np.testing.assert_array_equal(r["Not.out.Value"], (u <= 0.5).astype(float))
    np.testing.assert_array_equal(r["Xor.out.Value"], (np.abs(u) > 0.5).astype(float))


def test_hopsans_segare_and_dxsegare_are_a_round_ports_area_and_width(tmp_path: Path) -> None:
    """SignalSegare (area) and SignalDxSegare (width) of a round port: x uncovering it, its diameter from a
    signal or, unconnected, from its start value; closed below 0, the whole circle beyond the diameter (the
    segment from its central angle phi, (d^2/8)(phi - sin phi), and its chord 2 sqrt(x (d - x)))."""
    v = _value
    ramp = {"y_0#Value": v("-0.01"), "y_A#Value": v("0.1"), "t_start#Value": v("0"), "t_end#Value": v("1")}
    components = [
        ("SignalRamp", "Ramp", ramp), ("SignalConstant", "D", {"y#Value": v("0.06")}),
        ("SignalSegare", "Area", {"diameter#Value": v("1")}), ("SignalDxSegare", "Width", {}),
        ("SignalSegare", "Own", {"diameter#Value": v(".04")}),
    ]
    connections = [("Ramp.out", "Area.x"), ("D.y", "Area.diameter"), ("Ramp.out", "Width.x"),
                   ("D.y", "Width.diameter"), ("Ramp.out", "Own.x")]
    path = tmp_path / "segare.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    kinds = {hopsan: became for hopsan, _, became in imp.mapping}
    assert kinds["Area"] == "Function Area" and kinds["Width"] == "Function Width"
    t = np.array([0.0, 0.1, 0.25, 0.4, 0.55, 0.7, 1.0])
    r = imp.system.simulate(t_eval=t)
    x = -0.01 + 0.1 * t

    def area(d: float) -> np.ndarray:
        h = np.clip(x, 0.0, d)
        phi = 2.0 * np.arccos(1.0 - 2.0 * h / d)
        return d * d / 8.0 * (phi - np.sin(phi))

    np.testing.assert_allclose(r["Area.area.Value"], area(0.06), rtol=1e-12, atol=1e-10)  # acos near 1: 1e-11
    np.testing.assert_allclose(r["Own.area.Value"], area(0.04), rtol=1e-12, atol=1e-10)
    np.testing.assert_allclose(r["Width.width.Value"], 2.0 * np.sqrt(np.clip(x, 0, 0.06) * (0.06 - np.clip(x, 0, 0.06))),
                               rtol=1e-12, atol=1e-15)


def test_hopsans_single_gear_and_lossless_ball_screw_follow_their_closed_forms(tmp_path: Path) -> None:
    """MechanicRotationalInertiaWithSingleGear between two torque sources: J w2' = -omega T1 - T2 - B w2 (Hopsan's
    gear-ratio law with U = -omega), P1 turning at omega w2; MechanicBallScrew (ny = ny2 = 1) between a force source
    at its nut P1 and a torque source at P2: J w2' = (L/2 pi) F - T - B w2, the nut at v1 = -(L/2 pi) w2. Both from
    rest: w2 = (drive/B) (1 - exp(-B t/J)). The screw's efficiencies are refused with the reason."""
    v = _value
    components = [
        ("MechanicTorqueTransformer", "T1", {"T#Value": v("-3")}), ("MechanicTorqueTransformer", "T2", {"T#Value": v("2")}),
        ("MechanicRotationalInertiaWithSingleGear", "SG", {"omega#Value": v("2"), "B#Value": v("0.5"), "J": v("0.1")}),
        ("MechanicForceTransformer", "F", {"F#Value": v("1000")}), ("MechanicTorqueTransformer", "T3", {"T#Value": v("0.5")}),
        ("MechanicBallScrew", "BS", {"L#Value": v("0.01"), "ny#Value": v("1"), "ny2#Value": v("1"), "J#Value": v("0.001"),
                                     "B#Value": v("0.01")}),
    ]
    connections = [("T1.P1", "SG.P1"), ("SG.P2", "T2.P1"), ("F.P1", "BS.P1"), ("BS.P2", "T3.P1")]
    path = tmp_path / "gears.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    kinds = {hopsan: became for hopsan, _, became in imp.mapping}
    assert kinds["SG"] == "RotationalInertia SG" and kinds["BS"] == "Crank BS"
    t = np.array([0.0, 0.05, 0.2, 0.5, 1.0])
    r = imp.system.simulate(t_eval=t)
    w_gear = (2.0 * 3.0 - 2.0) / 0.5 * (1.0 - np.exp(-0.5 * t / 0.1))
    np.testing.assert_allclose(r["SG.P2.AngularVelocity"], w_gear, rtol=1e-5, atol=1e-8)
    np.testing.assert_allclose(r["SG.P1.AngularVelocity"], 2.0 * w_gear, rtol=1e-5, atol=1e-8)
    lead = 0.01 / (2.0 * np.pi)
    w_screw = (lead * 1000.0 - 0.5) / 0.01 * (1.0 - np.exp(-0.01 * t / 0.001))
    np.testing.assert_allclose(r["BS.P2.AngularVelocity"], w_screw, rtol=1e-5, atol=1e-8)
    np.testing.assert_allclose(r["BS.P1.Velocity"], -lead * w_screw, rtol=1e-5, atol=1e-10)
    lossy = [c if c[1] != "BS" else ("MechanicBallScrew", "BS", {"ny#Value": v("0.9"), "ny2#Value": v("1")}) for c in components]
    path.write_text(_hmf(lossy, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"BS.*efficiencies ny = 0\.9, ny2 = 1: only a lossless screw"):
        import_hopsan(path)


def test_hopsans_counter_counts_the_edges_of_its_input_it_is_asked_to(tmp_path: Path) -> None:
    """SignalCounter's r and f (bool) choose the edges counted: of a square wave of 1 Hz between -1 and 1 from
    t = 0 (rising at 0, 1, 2 s, falling at 0.5, 1.5 s), the rising ones, the falling ones, both; neither: 0."""
    v = _value
    square = {"y_0#Value": v("0"), "y_A#Value": v("1"), "f#Value": v("1"), "t_start#Value": v("0")}
    components = [("SignalSquareWave", "Sq", square),
                  ("SignalCounter", "Both", {}), ("SignalCounter", "Up", {"f": v("false")}),
                  ("SignalCounter", "Down", {"r": v("false")}), ("SignalCounter", "Neither", {"r": v("false"), "f": v("false")})]
    connections = [("Sq.out", f"{k}.in") for k in ("Both", "Up", "Down", "Neither")]
    path = tmp_path / "counter.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["Up"].option("edges") == "rising" and imp.system["Down"].option("edges") == "falling"
    t = np.array([0.0, 0.25, 0.75, 1.25, 1.75, 2.25])
    r = imp.system.simulate(t_eval=t)
    up, down = np.array([0, 1, 1, 2, 2, 3]), np.array([0, 0, 1, 1, 2, 2])
    np.testing.assert_allclose(r["Up.out.Value"], up, atol=1e-6)
    np.testing.assert_allclose(r["Down.out.Value"], down, atol=1e-6)
    np.testing.assert_allclose(r["Both.out.Value"], up + down, atol=1e-6)
    np.testing.assert_array_equal(r["Neither.out.Value"], np.zeros_like(t))


def test_hopsans_second_order_filter_and_high_pass_answer_a_step_with_their_continuous_laws(tmp_path: Path) -> None:
    """SignalSecondOrderFilter k (s^2/w1^2 + 2 d1 s/w1 + 1)/(s^2/w2^2 + 2 d2 s/w2 + 1) with k = 2, w1 = 5, d1 = 1,
    w2 = 20, d2 = 1 is 32 (s + 5)^2/(s + 20)^2: its step response 2 + 30 e^-20t - 360 t e^-20t; SignalHP2Filter
    (s^2/w^2)/(s^2/w^2 + 2 d s/w + 1) with w = 10, d = 1 is s^2/(s + 10)^2: e^-10t (1 - 10 t). The step at 1 s."""
    v = _value
    components = [
        ("SignalStep", "Step", {"y_0#Value": v("0"), "y_A#Value": v("1"), "t_step#Value": v("0")}),
        ("SignalSecondOrderFilter", "F2", {"k": v("2"), "omega_1": v("5"), "delta_1": v("1"), "omega_2": v("20"),
                                           "delta_2": v("1")}),
        ("SignalHP2Filter", "HP2", {"omega": v("10"), "delta": v("1")}),
    ]
    path = tmp_path / "filters2.hmf"
    text = _hmf(components, [("Step.out", "F2.in"), ("Step.out", "HP2.in")]).replace('start="0"', 'start="-1"')
    path.write_text(text, encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["F2"].option("order") == "2" and imp.system["HP2"].option("order") == "2"
    t = np.array([0.5, 1.02, 1.05, 1.1, 1.3, 2.0])
    tau = t - 1.0
    r = imp.system.simulate(t_eval=t, accuracy=1e-6)
    f2 = 2 + 30 * np.exp(-20 * tau) - 360 * tau * np.exp(-20 * tau)
    np.testing.assert_allclose(r["F2.out.Value"], np.where(tau >= 0, f2, 0.0), atol=1e-5)
    np.testing.assert_allclose(r["HP2.out.Value"], np.where(tau >= 0, np.exp(-10 * tau) * (1 - 10 * tau), 0.0),
                               atol=1e-6)


def test_hopsans_displays_and_loggers_are_dropped_and_gui_inputs_hold_their_start_values(tmp_path: Path) -> None:
    """SignalDisplay, SignalAnimationGauge, SignalAnimationLamp and SignalLogger compute nothing (dropped);
    SignalNumericalInput and SignalAnimationSwitch output their start value of out; SignalAnimationSlider
    min + (max - min) in, in at its start value where nothing drives it."""
    v = _value
    components = [
        ("SignalNumericalInput", "Num", {"out#Value": v("3")}), ("SignalAnimationSwitch", "Switch", {}),
        ("SignalAnimationSlider", "Slider", {"min": v("2"), "max": v("4"), "in#Value": v("0.5")}),
        ("SignalAnimationSlider", "Driven", {"min": v("2"), "max": v("4")}), ("SignalConstant", "C", {"y#Value": v("0.25")}),
        ("SignalDisplay", "Display", {}), ("SignalAnimationGauge", "Gauge", {}), ("SignalAnimationLamp", "Lamp", {}),
        ("SignalLogger", "Logger", {}),
    ]
    connections = [("Num.out", "Display.in"), ("Slider.out", "Gauge.in"), ("Switch.out", "Lamp.in"),
                   ("Num.out", "Logger.in"), ("Switch.out", "Logger.in"), ("C.y", "Driven.in")]
    path = tmp_path / "gui.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    kinds = {hopsan: became for hopsan, _, became in imp.mapping}
    assert all(kinds[k].startswith("dropped") for k in ("Display", "Gauge", "Lamp", "Logger"))
    assert not {"Display", "Gauge", "Lamp", "Logger"} & set(imp.system.components)
    r = imp.system.simulate(t_eval=[0.0, 1.0])
    assert list(r["Num.out.Value"]) == [3.0, 3.0] and list(r["Switch.out.Value"]) == [0.0, 0.0]
    assert list(r["Slider.out.Value"]) == [3.0, 3.0] and list(r["Driven.out.Value"]) == [2.5, 2.5]


@pytest.mark.parametrize("kind", sorted(REFUSED))
def test_blocks_hydroservo_cannot_follow_are_refused_with_why(tmp_path: Path, kind: str) -> None:
    path = tmp_path / "refused.hmf"
    path.write_text(_hmf([(kind, "Block", {})], []), encoding="utf-8")
    with pytest.raises(ModelFileError, match=rf"Block \({kind}: " + re.escape(REFUSED[kind][:40])):
        import_hopsan(path)
    assert kind not in LIBRARY


def test_rate_limits_of_the_wrong_sign_and_static_friction_below_the_kinetic_are_refused(tmp_path: Path) -> None:
    v = _value
    components = [
        ("SignalRateLimiter", "RL", {"c_up#Value": v("1"), "c_down#Value": v("1")}),
        ("MechanicTranslationalMassWithCoulombFriction", "M", {"f_s#Value": v("40"), "f_k#Value": v("45")}),
    ]
    path = tmp_path / "refused.hmf"
    path.write_text(_hmf(components, []), encoding="utf-8")
    with pytest.raises(ModelFileError) as err:
        read_hopsan(path)
    text = str(err.value)
    assert "RL (SignalRateLimiter): c_up = 1, c_down = 1: expected c_up >= 0 and c_down <= 0" in text
    assert "M (MechanicTranslationalMassWithCoulombFriction): f_s = 40 N, f_k = 45 N" in text


def test_a_mass_with_coulomb_friction_maps_to_the_stribeck_law_and_a_positioned_velocity_source(tmp_path: Path) -> None:
    """MechanicTranslationalMassWithCoulombFriction: m, b, f_s, f_k as Mass's m, B, F_c0 + F_s0 and F_c0 with
    stated velocity scales; a velocity transformer whose position input is connected takes its position from it
    (option position = 'input'). Pushed by 30 N (below f_s = 50 N) the mass stays; by 100 N it slides against
    f_k = 45 N and b = 10 N s/m: v = (100 - 45)/10 (1 - exp(-t b/m))."""
    v = _value
    components = [
        ("MechanicTranslationalMassWithCoulombFriction", "Stuck", {"m": v("10"), "b#Value": v("10"), "f_s#Value": v("50"),
                                                                   "f_k#Value": v("45")}),
        ("MechanicTranslationalMassWithCoulombFriction", "Slides", {"m": v("10"), "b#Value": v("10"),
                                                                    "f_s#Value": v("50"), "f_k#Value": v("45")}),
        ("MechanicForceTransformer", "F30", {"F#Value": v("30")}),
        ("MechanicForceTransformer", "F100", {"F#Value": v("100")}),
        ("MechanicVelocityTransformer", "VS", {}),
        ("SignalConstant", "X", {"y#Value": v("0.25")}),
        ("SignalConstant", "V", {"y#Value": v("0.1")}),
        ("MechanicTranslationalSpring", "K", {"k#Value": v("1000")}),
        ("MechanicFixedPosition", "G", {}),
    ]
    connections = [
        ("F30.P1", "Stuck.P1"), ("F100.P1", "Slides.P1"),
        ("X.y", "VS.x"), ("V.y", "VS.v"), ("VS.Pm1", "K.P1"), ("K.P2", "G.Pm1"),
    ]
    path = tmp_path / "coulomb.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    mass = imp.system["Slides"]
    assert (mass.values["B"], mass.values["F_c0"], mass.values["F_s0"], mass.values["k_spring"]) == (10.0, 45.0, 5.0, 0.0)
    assert imp.system["VS"].option("position") == "input"
    t = np.array([0.0, 0.5, 1.0, 2.0])
    r = imp.system.simulate(t_eval=t, accuracy=1e-8)
    assert np.max(np.abs(r["Stuck.P1.Velocity"])) < 2e-5  # creeping at most at about v_reg
    # Hopsan's force at P1 pushes the mass towards +x at P2: P1 moves outward at -v
    np.testing.assert_allclose(r["Slides.P1.Velocity"], -5.5 * (1.0 - np.exp(-t)), atol=2e-3)
    np.testing.assert_allclose(r["VS.Pm1.Position"], 0.25)
    np.testing.assert_allclose(r["VS.Pm1.Velocity"], 0.1)
    np.testing.assert_allclose(r["K.P1.Force"], 1000.0 * 0.25, rtol=1e-9)  # Hopsan's k (x1 + x2), ends outward


def test_multiport_masses_sum_the_forces_of_every_connection_and_a_pulley_doubles_its_ropes(tmp_path: Path) -> None:
    """[Hopsan2026] Mechanic/Linear/MechanicMultiPortTranslationalMass.hpp, MechanicTranslationalMassWithCoulomb-
    FrictionAndMultiPorts.hpp, MechanicPulley.hpp, MechanicFixedPositionMultiPort.hpp, each against its closed
    form: two forces of 30 N and 50 N on a multiport mass's P1 (m 10 kg, B 20 N s/m) add, v = 80/B (1 - exp(-B t/m));
    on the friction multiport mass (f_s 50 N, f_k 45 N, b 10 N s/m) 2 x 20 N keep it stuck and 2 x 40 N slide it
    against f_k, v = 35/b (1 - exp(-b t/m)); a pulley (m 1 kg, B 10 N s/m) pulled at P1 by 100 N, P2 free, moves at
    v_2 = 2 F/B (1 - exp(-B t/m)), P1 twice as fast the other way; another held at P2 by a spring of 1000 N/m on a
    multiport fixed point comes to rest with the spring's force 2 F and P1 at -2 x_2, while a second spring on that
    fixed point, pushed by 50 N, is compressed by 50 N / 2000 N/m."""
    v = _value
    components = [
        ("MechanicMultiPortTranslationalMass", "M", {"m#Value": v("10"), "B#Value": v("20")}),
        ("MechanicForceTransformer", "Fa", {"F#Value": v("30")}),
        ("MechanicForceTransformer", "Fb", {"F#Value": v("50")}),
        ("MechanicTranslationalMassWithCoulombFrictionAndMultiPorts", "Stuck",
         {"m": v("10"), "b#Value": v("10"), "f_s#Value": v("50"), "f_k#Value": v("45")}),
        ("MechanicTranslationalMassWithCoulombFrictionAndMultiPorts", "Slides",
         {"m": v("10"), "b#Value": v("10"), "f_s#Value": v("50"), "f_k#Value": v("45")}),
        ("MechanicForceTransformer", "S1", {"F#Value": v("20")}),
        ("MechanicForceTransformer", "S2", {"F#Value": v("20")}),
        ("MechanicForceTransformer", "L1", {"F#Value": v("40")}),
        ("MechanicForceTransformer", "L2", {"F#Value": v("40")}),
        ("MechanicPulley", "Free", {"m": v("1"), "B#Value": v("10")}),
        ("MechanicForceTransformer", "Rope", {"F#Value": v("100")}),
        ("MechanicPulley", "Held", {"m": v("1"), "B#Value": v("10")}),
        ("MechanicForceTransformer", "Rope2", {"F#Value": v("100")}),
        ("MechanicTranslationalSpring", "K", {"k#Value": v("1000")}),
        ("MechanicFixedPositionMultiPort", "G", {}),
        ("MechanicTranslationalSpring", "K2", {"k#Value": v("2000")}),
        ("MechanicTranslationalMass", "M2", {"m#Value": v("1"), "B#Value": v("100"), "k#Value": v("0")}),
        ("MechanicForceTransformer", "Push", {"F#Value": v("50")}),
    ]
    connections = [
        ("Fa.P1", "M.P1"), ("Fb.P1", "M.P1"), ("S1.P1", "Stuck.P1"), ("S2.P1", "Stuck.P1"),
        ("L1.P1", "Slides.P1"), ("L2.P1", "Slides.P1"), ("Rope.P1", "Free.P1"),
        ("Rope2.P1", "Held.P1"), ("Held.P2", "K.P1"), ("K.P2", "G.Pm1"),
        ("Push.P1", "M2.P1"), ("M2.P2", "K2.P1"), ("K2.P2", "G.Pm1"),
    ]
    path = tmp_path / "multiport.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    mapped = dict((h, t) for h, t, _ in imp.mapping)
    assert mapped["Held"] == "MechanicPulley" and mapped["G"] == "MechanicFixedPositionMultiPort"
    t = np.array([0.0, 0.1, 0.3, 3.0])
    r = imp.system.simulate(t_eval=t, accuracy=1e-7)
    # Hopsan's force at P1 pushes the mass towards +x at P2: P1 moves outward at -v (P2 is free: not logged)
    np.testing.assert_allclose(r["M.P1.Velocity"], -4.0 * (1.0 - np.exp(-2.0 * t)), atol=1e-5)
    assert np.max(np.abs(r["Stuck.P1.Velocity"])) < 3e-5  # creeping at most at about v_reg
    np.testing.assert_allclose(r["Slides.P1.Velocity"], -3.5 * (1.0 - np.exp(-t)), atol=2e-3)
    np.testing.assert_allclose(r["Free.P1.Velocity"], -40.0 * (1.0 - np.exp(-10.0 * t)), atol=1e-4)
    np.testing.assert_allclose(r["Free.x"], 2.0 * (10.0 * t - 1.0 + np.exp(-10.0 * t)), atol=1e-5)  # P2's
    assert float(r["K.P1.Force"][-1]) == pytest.approx(200.0, rel=1e-6)
    assert float(r["Held.P2.Position"][-1]) == pytest.approx(0.2, rel=1e-6)
    assert float(r["Held.P1.Position"][-1]) == pytest.approx(-0.4, rel=1e-6)
    assert float(r["K2.P1.Force"][-1]) == pytest.approx(50.0, rel=1e-6)
    assert float(r["M2.P2.Position"][-1]) == pytest.approx(0.025, rel=1e-6)
    np.testing.assert_allclose(r["G.Pm1.Velocity"], 0.0)
    # connections to a multiport that start at different positions are refused (hydroservo's port has one)
    components[13] = ("MechanicTranslationalSpring", "K", {"k#Value": v("1000"), "P2#Position": v("0.1", "m")})
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"G \(MechanicFixedPositionMultiPort\): the connections to Pm1 start at "
                                             r"different positions"):
        read_hopsan(path)


def test_hopsans_spring_with_a_free_length_pushes_from_where_it_is_relaxed(tmp_path: Path) -> None:
    """[Hopsan2026] Mechanic/Linear/MechanicSpring.hpp: f = Ks (x_m1 + x_m2 - x0), Hopsan's node force from its
    ends' positions whatever they start at: a mass (m 1 kg, B 60 N s/m) between a force of 100 N and such a spring
    (Ks 1000 N/m, x0 0.05 m) on a fixed point comes to rest at x = x0 + F/Ks = 0.15 m; at the start, both ends at
    0, the spring pulls with Ks x0 = 50 N (Hopsan's force -50 N)."""
    v = _value
    components = [
        ("MechanicForceTransformer", "F", {"F#Value": v("100")}),
        ("MechanicTranslationalMass", "M", {"m#Value": v("1"), "B#Value": v("60"), "k#Value": v("0")}),
        ("MechanicSpring", "K", {"Ks#Value": v("1000"), "x0#Value": v("0.05")}),
        ("MechanicFixedPosition", "G", {}),
    ]
    path = tmp_path / "spring.hmf"
    path.write_text(_hmf(components, [("F.P1", "M.P1"), ("M.P2", "K.Pm1"), ("K.Pm2", "G.Pm1")]), encoding="utf-8")
    r = import_hopsan(path).system.simulate(t_eval=[0.0, 1.0], accuracy=1e-9)
    assert float(r["K.Pm1.Force"][0]) == pytest.approx(-50.0, rel=1e-9)
    assert float(r["M.P2.Position"][-1]) == pytest.approx(0.15, rel=1e-6)
    assert float(r["K.Pm1.Force"][-1]) == pytest.approx(100.0, rel=1e-6)


def test_hopsans_sensors_plug_and_lossless_connectors_against_their_laws(tmp_path: Path) -> None:
    """[Hopsan2026] Hydraulic/Sensors/HydraulicDifferentialPressureSensor.hpp (p_1 - p_2), HydraulicPowerSensor.hpp
    (p q, Hopsan's absolute pressure times its node's flow), Hydraulic/Sources&Sinks/HydraulicPlugQ.hpp (q = 0),
    Hydraulic/Restrictors/HydraulicLossLessConnector.hpp and HydraulicLossLessTConnector.hpp (their nodes joined,
    p equal at every port, up to q/G = q/1e-6 Pa): a 50 bar (absolute) source drains through laminar orifices
    (Kc = 1e-11 and 2e-11 m^3/s/Pa) to a tank, directly, through a lossless connector and a volume, and through a T
    connector and two volumes; a volume closed by a plug comes to the source's pressure; at rest each flow is
    Kc (p - p_tank)."""
    v = _value
    ps, pt = 50e5, 1e5
    components = [
        ("HydraulicPressureSourceC", "S", {"p#Value": v(repr(ps), "Pa")}),
        ("HydraulicTankC", "T", {}),
        ("HydraulicLaminarOrifice", "O", {"Kc#Value": v("1e-11")}),
        ("HydraulicDifferentialPressureSensor", "DP", {}),
        ("HydraulicPowerSensor", "W", {}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v(repr(ps), "Pa")}),
        ("HydraulicLaminarOrifice", "O2", {"Kc#Value": v("1e-11")}),
        ("HydraulicVolume", "V", {}),
        ("HydraulicPlugQ", "Plug", {}),
        ("HydraulicPressureSourceC", "S3", {"p#Value": v(repr(ps), "Pa")}),
        ("HydraulicLosslessConnector", "L", {}),
        ("HydraulicVolume", "VL", {}),
        ("HydraulicLaminarOrifice", "OL", {"Kc#Value": v("1e-11")}),
        ("HydraulicTankC", "TL", {}),
        ("HydraulicPressureSourceC", "S4", {"p#Value": v(repr(ps), "Pa")}),
        ("HydraulicLosslessTConnector", "LT", {}),
        ("HydraulicVolume", "V2", {}),
        ("HydraulicVolume", "V3", {}),
        ("HydraulicLaminarOrifice", "O3", {"Kc#Value": v("1e-11")}),
        ("HydraulicLaminarOrifice", "O4", {"Kc#Value": v("2e-11")}),
        ("HydraulicTankC", "T3", {}),
        ("HydraulicTankC", "T4", {}),
    ]
    connections = [
        ("S.P1", "O.P1"), ("O.P2", "T.P1"), ("DP.P1", "O.P1"), ("DP.P2", "O.P2"), ("W.P1", "O.P1"),
        ("S2.P1", "O2.P1"), ("O2.P2", "V.P1"), ("V.P2", "Plug.P1"),
        ("S3.P1", "L.P1"), ("L.P2", "VL.P1"), ("VL.P2", "OL.P1"), ("OL.P2", "TL.P1"),
        ("S4.P1", "LT.P1"), ("LT.P2", "V2.P1"), ("LT.P3", "V3.P1"), ("V2.P2", "O3.P1"), ("V3.P2", "O4.P1"),
        ("O3.P2", "T3.P1"), ("O4.P2", "T4.P1"),
    ]
    path = tmp_path / "sensors.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    r = import_hopsan(path).system.simulate(t_eval=[0.0, 3.0], accuracy=1e-9)
    q = 1e-11 * (ps - pt)
    assert float(r["DP.out.Value"][-1]) == pytest.approx(ps - pt, rel=1e-9)
    assert float(r["W.out.Value"][-1]) == pytest.approx(ps * -q, rel=1e-9)  # the orifice takes q from S's node
    assert float(r["Plug.P1.Flow"][-1]) == 0.0
    assert float(r["V.P2.Pressure"][-1]) == pytest.approx(ps, rel=1e-6)
    # the lossless connectors' nodes at the source's pressure, within q/G
    assert abs(float(r["VL.P1.Pressure"][-1]) - ps) < 1.01 * q / 1e-6
    assert float(r["L.P2.Flow"][-1]) == pytest.approx(q, rel=1e-4)
    assert float(r["L.P1.Flow"][-1]) == pytest.approx(-q, rel=1e-4)
    assert abs(float(r["V2.P1.Pressure"][-1]) - ps) < 3.1 * q / 1e-6
    assert float(r["LT.P2.Flow"][-1]) == pytest.approx(q, rel=1e-4)
    assert float(r["LT.P3.Flow"][-1]) == pytest.approx(2.0 * q, rel=1e-4)
    assert float(r["LT.P1.Flow"][-1]) == pytest.approx(-3.0 * q, rel=1e-4)


def test_hopsans_transmission_line_and_hose_are_ladders_of_their_lines(tmp_path: Path) -> None:
    """[Hopsan2026] Hydraulic/Volumes&Lines/HydraulicTLMlossless.hpp: a flow q into a line of impedance Z_c held at
    its other end raises its pressure by Z_c q until the wave returns (2T); HydraulicHose.hpp: once its waves have
    died out, a hose passes q with the Hagen-Poiseuille drop 128 eta l q/(pi d^4) and none of its wall's. Both are
    ladders of the segments that carry their waves up to the Nyquist frequency of Hopsan's step (5 T/Ts), or of the
    import's line_segments."""
    v = _value
    start = {"P1#Pressure": v("1e6", "Pa"), "P2#Pressure": v("1e6", "Pa")}
    components = [
        ("HydraulicFlowSourceQ", "Q", {"q#Value": v("1e-5")}),
        ("HydraulicTLMlossless", "TLM", {"Z_c#Value": v("1e9"), "deltat": v("0.002", "s"), **start}),
        ("HydraulicLaminarOrifice", "O", {"Kc#Value": v("1e-3")}),
        ("HydraulicPressureSourceC", "S", {"p#Value": v("1e6", "Pa")}),
        ("HydraulicFlowSourceQ", "Q2", {"q#Value": v("1e-5")}),
        ("HydraulicHose", "H", {"d#Value": v("0.003"), "l#Value": v("0.2"), "eta_w": v("0.01"), **start}),
        ("HydraulicLaminarOrifice", "O2", {"Kc#Value": v("1e-3")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("1e6", "Pa")}),
    ]
    connections = [("Q.P1", "TLM.P1"), ("TLM.P2", "O.P1"), ("O.P2", "S.P1"),
                   ("Q2.P1", "H.P1"), ("H.P2", "O2.P1"), ("O2.P2", "S2.P1")]
    path, hose_path = tmp_path / "line.hmf", tmp_path / "hose.hmf"
    path.write_text(_hmf(components[:4], connections[:3]), encoding="utf-8")
    hose_path.write_text(_hmf(components[4:], connections[3:]), encoding="utf-8")
    line, hose = import_hopsan(path).system, import_hopsan(hose_path).system
    assert type(line["TLM"]).__name__ == "LosslessLine" and line["TLM"].segments == 100  # 5 T/Ts: T 2 ms, Ts 0.1 ms
    assert type(hose["H"]).__name__ == "Line" and hose["H"].segments == 10 and hose["H"].viscous_wall  # T = 0.19 ms
    assert hose["H"].values["nu"] == pytest.approx(0.03 / 870.0) and hose["H"].values["eta_w"] == 0.01
    assert hose["H"].turbulent and not line["TLM"].turbulent  # Blasius' friction above Re 2300, as Hopsan's hose
    t = np.linspace(0.0, 0.004, 401)
    p = line.simulate(t_eval=t)["TLM.P1.Pressure"]
    assert np.mean(p[(t > 0.001) & (t < 0.003)]) == pytest.approx(1e6 + 1e9 * 1e-5, rel=1e-4)
    r = hose.simulate(t_eval=[0.0, 0.6], method="rodas3")  # its lightly damped waves: an L-stable method
    drop = 128 * 0.03 * 0.2 * 1e-5 / (np.pi * 0.003**4)
    assert r["H.P1.Pressure"][-1] - r["H.P2.Pressure"][-1] == pytest.approx(drop, rel=1e-4)
    assert r["H.P2.Flow"][-1] == pytest.approx(-1e-5, rel=1e-6)  # Hopsan's flow into the line at P2
    from hydroservo.workflows.hopsan import ImportHopsan

    assert ImportHopsan(path, line_segments=30).imported.system["TLM"].segments == 30  # import-hopsan --line-segments
    with pytest.raises(ModelFileError, match="line_segments = 0: expected a whole number from 1 to 200"):
        import_hopsan(path, line_segments=0)
    # a filter tied to Hopsan's step and a line not at rest at the start are refused, named
    components[1] = ("HydraulicTLMlossless", "TLM", {"alpha#Value": v("0.5"), **start})
    components[5] = ("HydraulicHose", "H", {"P1#Pressure": v("2e6", "Pa"), "P2#Pressure": v("1e6", "Pa")})
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError) as refused:
        import_hopsan(path)
    assert "TLM (HydraulicTLMlossless): alpha = 0.5" in str(refused.value)
    assert "H (HydraulicHose): start values P1#Pressure = 2e+06 Pa, P2#Pressure = 1e+06 Pa" in str(refused.value)


def test_a_multiport_rotational_inertia_sums_the_torques_of_its_connections(tmp_path: Path) -> None:
    """[Hopsan2026] Mechanic/Rotational/MechanicRotationalInertiaMultiPort.hpp: J θ'' = Σt_1 - Σt_2 - B θ', from
    rest at 0: torques of 3 and 5 N m on P1 (J 2 kg m², B 4 N m s/rad, P2 free) turn P1 at
    -(8/B)(1 - exp(-B t/J)), its angle the integral; start angles of P1 and P2 that do not add to 0 are refused."""
    v = _value
    components = [
        ("MechanicRotationalInertiaMultiPort", "J", {"J#Value": v("2"), "B#Value": v("4")}),
        ("MechanicTorqueTransformer", "Ta", {"T#Value": v("3")}),
        ("MechanicTorqueTransformer", "Tb", {"T#Value": v("5")}),
    ]
    connections = [("Ta.P1", "J.P1"), ("Tb.P1", "J.P1")]
    path = tmp_path / "inertia.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    t = np.array([0.0, 0.2, 0.5, 1.0])
    r = import_hopsan(path).system.simulate(t_eval=t, accuracy=1e-9)
    np.testing.assert_allclose(r["J.P1.AngularVelocity"], -2.0 * (1.0 - np.exp(-2.0 * t)), atol=1e-7)
    np.testing.assert_allclose(r["J.P1.Angle"], -2.0 * t + (1.0 - np.exp(-2.0 * t)), atol=1e-7)
    for i in (1, 2):
        components[i][2]["P1#Angle"] = v("0.3", "rad")
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"J \(MechanicRotationalInertiaMultiPort\): start angles of P1 and P2 "
                                             r"that add to 0.3 rad"):
        read_hopsan(path)


def test_hopsans_spring_with_slack_pulls_while_stretched_and_goes_slack(tmp_path: Path) -> None:
    """[Hopsan2026] Mechanic/Linear/MechanicTranslationalSpringWithSlack.hpp: f = k (x_1 + x_2) while x_1 + x_2 <= 0
    (its ends' positions inward: stretched), else 0. An end moved by a velocity transformer at -0.2 m/s (the other
    fixed) pulls with k (-0.2 t); one moved at +0.2 m/s leaves it slack (the plain spring pushes: k 0.2 t). A start
    force the law does not give at the start positions is refused."""
    v = _value
    components = [
        ("MechanicVelocityTransformer", "Out", {"v#Value": v("-0.2")}),
        ("MechanicTranslationalSpringWithSlack", "Rope", {"k#Value": v("1000")}),
        ("MechanicFixedPosition", "G", {}),
        ("MechanicVelocityTransformer", "In", {"v#Value": v("0.2")}),
        ("MechanicTranslationalSpringWithSlack", "Slack", {"k#Value": v("1000")}),
        ("MechanicTranslationalSpring", "Plain", {"k#Value": v("1000")}),
        ("MechanicFixedPosition", "G2", {}),
        ("MechanicVelocityTransformer", "In2", {"v#Value": v("0.2")}),
        ("MechanicFixedPosition", "G3", {}),
    ]
    connections = [("Out.Pm1", "Rope.P1"), ("Rope.P2", "G.Pm1"), ("In.Pm1", "Slack.P1"), ("Slack.P2", "G2.Pm1"),
                   ("In2.Pm1", "Plain.P1"), ("Plain.P2", "G3.Pm1")]
    path = tmp_path / "slack.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    t = np.array([0.0, 0.5, 1.0])
    r = import_hopsan(path).system.simulate(t_eval=t, accuracy=1e-9)
    np.testing.assert_allclose(r["Rope.P1.Force"], -200.0 * t, atol=1e-9)
    np.testing.assert_allclose(r["Slack.P1.Force"], 0.0, atol=1e-9)
    np.testing.assert_allclose(r["Plain.P1.Force"], 200.0 * t, atol=1e-9)
    components[1] = ("MechanicTranslationalSpringWithSlack", "Rope", {"k#Value": v("1000"), "P1#Force": v("5", "N"),
                                                                      "P2#Force": v("5", "N")})
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"Rope \(MechanicTranslationalSpringWithSlack\): k = 1000 N/m, start "
                                             r"forces 5 N and 5 N"):
        read_hopsan(path)


def test_hopsans_rack_and_pinion_turns_its_pinion_through_the_gear_ratio(tmp_path: Path) -> None:
    """[Hopsan2026] Mechanic/Rotational/MechanicRackAndPinion.hpp: J w' = omega f_1 - t_2 - B w, the rack at
    -omega times the angle: 10 N on the rack (omega 0.2 m/rad, J 0.5 kg m², B 4 N m s/rad, the pinion's port free)
    moves it at -omega w = -0.1 (1 - exp(-8 t)) outward; a spring k other than 0 is refused."""
    v = _value
    components = [
        ("MechanicRackAndPinion", "RP", {"omega#Value": v("0.2"), "J#Value": v("0.5"), "B#Value": v("4")}),
        ("MechanicForceTransformer", "F", {"F#Value": v("10")}),
    ]
    path = tmp_path / "rack.hmf"
    path.write_text(_hmf(components, [("F.P1", "RP.P1")]), encoding="utf-8")
    t = np.array([0.0, 0.1, 0.5, 2.0])
    r = import_hopsan(path).system.simulate(t_eval=t, accuracy=1e-9)
    np.testing.assert_allclose(r["RP.P1.Velocity"], -0.1 * (1.0 - np.exp(-8.0 * t)), atol=1e-8)
    np.testing.assert_allclose(r["RP.P1.Position"], -0.1 * (t - (1.0 - np.exp(-8.0 * t)) / 8.0), atol=1e-8)
    components[0] = ("MechanicRackAndPinion", "RP", {"omega#Value": v("0.2"), "k": v("3")})
    path.write_text(_hmf(components, [("F.P1", "RP.P1")]), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"RP \(MechanicRackAndPinion\): omega = 0.2 m/rad, J = 1 kg m\^2, k = 3"):
        read_hopsan(path)


def test_blocks_that_start_at_their_input_take_the_value_driving_it_at_the_start(tmp_path: Path) -> None:
    """Hopsan initialises a rate limiter's output to its input, and a 4/2 on/off valve's spool to its input
    limited to the stroke: driven by a step of 1.1 before its edge, the limiter starts at 1.1 (not the file's
    start value of 'in', 0) and the spool fully open. Hydraulic42OnOffValveTest differed by 40 % otherwise."""
    components = [
        ("SignalStep", "Step", {"y_0#Value": ("1.1", ""), "y_A#Value": ("-1.2", ""), "t_step#Value": ("1", "s")}),
        ("SignalRateLimiter", "RL", {"c_up#Value": ("0.2", ""), "c_down#Value": ("-0.2", ""), "in#Value": ("0", "")}),
        ("Hydraulic42DirectionalValve", "V", {"in#Value": ("0", ""), "x_vmax#Value": ("0.01", "m"),
                                              "d#Value": ("0.01", "m"), "C_q#Value": ("0.67", "")}),
        ("HydraulicPressureSourceC", "S", {"p#Value": ("1e6", "Pa")}),
        ("HydraulicTankC", "T", {}),
        ("HydraulicTankC", "TA", {}),
        ("HydraulicTankC", "TB", {}),
    ]
    connections = [("Step.out", "RL.in"), ("RL.out", "V.in"), ("S.P1", "V.PP"), ("T.P1", "V.PT"),
                   ("TA.P1", "V.PA"), ("TB.P1", "V.PB")]
    path = tmp_path / "starts.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    system = read_hopsan(path)
    assert system["RL"].values["y0"] == pytest.approx(1.1)
    assert system.initial["V_spool.s"] == pytest.approx(1.0)


def test_rotational_inertia_torque_and_angular_velocity_sources_and_sensors(tmp_path: Path) -> None:
    """MechanicRotationalInertia (J, B, k) as RotationalInertia, MechanicTorqueTransformer as TorqueSource, the
    theta source and the angular-velocity transformer as AngularVelocitySource, the angle, speed and torque
    sensors reading Hopsan's node variables. A torque T = 4 N m at P1 turns the inertia (J 0.5, B 2) at P2 along
    +θ: ω = T/B (1 - exp(-B t/J)); a theta source whose thetain is connected takes its angle from it."""
    v = _value
    components = [
        ("MechanicRotationalInertia", "J", {"J": v("0.5"), "B#Value": v("2"), "k#Value": v("0")}),
        ("MechanicTorqueTransformer", "T", {"T#Value": v("4")}),
        ("MechanicAngularVelocitySensor", "W", {}),
        ("MechanicAngleSensor", "A", {}),
        ("MechanicTorqueSensor", "Q", {}),
        ("MechanicTorqueTransformer", "T0", {"T#Value": v("0")}),
        ("MechanicThetaSource", "TS", {"omega#Value": v("3")}),
        ("SignalConstant", "Th", {"y#Value": v("0.7")}),
        ("MechanicTorqueTransformer", "T1", {"T#Value": v("0")}),
        ("MechanicAngularVelocityTransformer", "AV", {"omega#Value": v("-2")}),
    ]
    connections = [
        ("T.P1", "J.P1"), ("T0.P1", "J.P2"), ("W.P1", "J.P2"), ("A.P1", "J.P2"), ("Q.P1", "J.P1"),
        ("TS.Pmr1", "T1.P1"), ("Th.y", "TS.thetain"), ("AV.out", "T0.P1"),
    ]
    path = tmp_path / "rot.hmf"
    # the angular velocity transformer drives the node of T0 and J.P2 twice: not Hopsan's C/Q alternation
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match="J.P2"):
        read_hopsan(path)
    connections[-1] = ("AV.out", "T1.P1")
    connections[-3] = ("TS.Pmr1", "T2.P1")
    components.append(("MechanicTorqueTransformer", "T2", {"T#Value": v("0")}))
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert (imp.system["J"].values["J"], imp.system["J"].values["B_rot"]) == (0.5, 2.0)
    assert imp.system["TS"].option("position") == "input" and imp.system["AV"].option("position") == "integral"
    t = np.array([0.0, 0.2, 0.5, 1.0])
    r = imp.system.simulate(t_eval=t, accuracy=1e-9)
    omega = 2.0 * (1.0 - np.exp(-4.0 * t))
    np.testing.assert_allclose(r["W.out.Value"], omega, atol=1e-6)
    np.testing.assert_allclose(r["J.P2.AngularVelocity"], omega, atol=1e-6)
    np.testing.assert_allclose(r["J.P1.AngularVelocity"], -omega, atol=1e-6)
    np.testing.assert_allclose(r["A.out.Value"], 2.0 * (t - 0.25 * (1.0 - np.exp(-4.0 * t))), atol=1e-6)
    np.testing.assert_allclose(r["Q.out.Value"][1:], 4.0)
    np.testing.assert_allclose(r["TS.Pmr1.Angle"], 0.7)
    np.testing.assert_allclose(r["TS.Pmr1.AngularVelocity"], 3.0)
    np.testing.assert_allclose(r["AV.out.Angle"], -2.0 * t, atol=1e-9)


def test_hopsans_q_type_motors_turn_against_their_load_with_hopsans_displacement_and_leakage(tmp_path: Path) -> None:
    """HydraulicVariableDisplacementMotorQ and HydraulicFixedDisplacementMotorQ: J ω' = ε D_m/2π (p1 - p2) - B_m ω
    - T3, the flow into P1 ε D_m/2π ω + C (p1 - p2) (C_im, C_lm). Between 100 bar and 1 bar (absolute) against
    a torque source of 20 N m each settles at ω = (ε D Δp - T)/B_m; a driven eps passes a Saturation to [-1, 1]
    (Hopsan limits it), a constant one outside it is refused."""
    v = _value
    D = 5e-5 / (2.0 * np.pi)
    components = [
        ("HydraulicVariableDisplacementMotorQ", "MV", {"D_m#Value": v("5e-5"), "B_m#Value": v("0.5"),
                                                       "C_im#Value": v("1e-11"), "J_m#Value": v("0.01"),
                                                       "eps#Value": v("0.5")}),
        ("HydraulicFixedDisplacementMotorQ", "MF", {"D_m#Value": v("5e-5"), "B_m#Value": v("0.5"),
                                                    "C_lm#Value": v("2e-11"), "J_m#Value": v("0.01")}),
        ("HydraulicPressureSourceC", "PH", {"p#Value": v("1e7", "Pa")}),
        ("HydraulicTankC", "PL", {"p": v("1e5", "Pa")}),
        ("HydraulicPressureSourceC", "PH2", {"p#Value": v("1e7", "Pa")}),
        ("HydraulicTankC", "PL2", {"p": v("1e5", "Pa")}),
        ("MechanicTorqueTransformer", "TV", {"T#Value": v("20")}),
        ("MechanicTorqueTransformer", "TF", {"T#Value": v("20")}),
    ]
    connections = [
        ("MV.P1", "PH.P1"), ("MV.P2", "PL.P1"), ("MV.P3", "TV.P1"),
        ("MF.P1", "PH2.P1"), ("MF.P2", "PL2.P1"), ("MF.P3", "TF.P1"),
    ]
    path = tmp_path / "motors.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    mv, mf = imp.system["MV"], imp.system["MF"]
    assert mv.values["D"] == pytest.approx(D) and mv.values["C_im"] == 1e-11 and mf.values["C_im"] == 2e-11
    assert mv.option("inlet") == "floor" and mv.values["C_em"] == 0.0 and mv.values["eta_hm"] == 1.0
    r = imp.system.simulate(t_end=1.0)
    dp = 1e7 - 1e5
    for name, eps, leak in (("MV", 0.5, 1e-11), ("MF", 1.0, 2e-11)):
        omega = (eps * D * dp - 20.0) / 0.5
        assert r[f"{name}.P3.AngularVelocity"][-1] == pytest.approx(omega, rel=1e-6)
        assert r[f"{name}.P3.Torque"][-1] == pytest.approx(20.0)
        # Hopsan's flow at P1 counts out of the motor
        assert r[f"{name}.P1.Flow"][-1] == pytest.approx(-(eps * D * omega + leak * dp), rel=1e-6)
    bad = [("HydraulicVariableDisplacementMotorQ", "MV", {"eps#Value": v("1.5")}), *components[1:]]
    path.write_text(_hmf(bad, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"eps = 1\.5 outside \[-1, 1\]"):
        read_hopsan(path)
    ramp = ("SignalRamp", "R", {"y_0#Value": v("0"), "y_A#Value": v("3"), "t_start#Value": v("0"), "t_end#Value": v("3")})
    path.write_text(_hmf([*components, ramp], [*connections, ("R.out", "MV.eps")]), encoding="utf-8")
    imp = import_hopsan(path)
    r = imp.system.simulate(t_eval=[0.0, 0.5, 2.0, 3.0])
    np.testing.assert_allclose(r["MV_eps.y"], [0.0, 0.5, 1.0, 1.0], atol=1e-9)


def test_hopsans_shafts_and_torsional_spring_are_torsional_springs_in_the_limit_of_a_vanishing_step(
    tmp_path: Path,
) -> None:
    """MechanicRotShaft (Ks), MechanicRotShaftG (Ks = π/32 (dy⁴ − di⁴) G/len) and MechanicTorsionalSpring (k):
    transmission-line springs whose impedance and numerical damping (alpha) vanish with the step, so
    TorsionalSprings of that stiffness. A theta source at 2 rad/s drags an inertia (J 0.5, no damping) through
    the shaft: the twist swings as (ω/ω_n) sin(ω_n t); alpha outside [0, 1) is refused."""
    v = _value
    components = [
        ("MechanicThetaSource", "S", {"omega#Value": v("2")}),
        ("MechanicRotShaft", "Shaft", {"Ks#Value": v("200"), "alpha#Value": v("0.9")}),
        ("MechanicRotationalInertia", "J", {"J": v("0.5"), "B#Value": v("0"), "k#Value": v("0")}),
        ("MechanicTorqueTransformer", "T", {"T#Value": v("0")}),
        ("MechanicRotShaftG", "G", {"dy#Value": v("0.05"), "di#Value": v("0.01"), "len#Value": v("2"),
                                    "G#Value": v("8e10")}),
        ("MechanicTorsionalSpring", "K", {"k": v("300")}),
        ("MechanicAngularVelocityTransformer", "W1", {}),
        ("MechanicAngularVelocityTransformer", "W2", {}),
        ("MechanicAngularVelocityTransformer", "W3", {}),
    ]
    connections = [("S.Pmr1", "Shaft.Pmr1"), ("Shaft.Pmr2", "J.P1"), ("J.P2", "T.P1"),
                   ("G.Pmr1", "W1.out"), ("G.Pmr2", "W2.out"), ("K.P1", "W3.out")]
    path = tmp_path / "shafts.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["Shaft"].values["k_rot"] == 200.0 and imp.system["K"].values["k_rot"] == 300.0
    assert imp.system["G"].values["k_rot"] == pytest.approx(np.pi / 32.0 * (0.05**4 - 0.01**4) * 8e10 / 2.0)
    t = np.linspace(0.0, 1.0, 11)
    r = imp.system.simulate(t_eval=t, accuracy=1e-9)
    wn = np.sqrt(200.0 / 0.5)
    np.testing.assert_allclose(r["J.P2.Angle"], 2.0 * t - 2.0 / wn * np.sin(wn * t), atol=1e-6)
    np.testing.assert_allclose(r["Shaft.Pmr2.Torque"], 200.0 * 2.0 / wn * np.sin(wn * t), atol=1e-4)
    components[1] = ("MechanicRotShaft", "Shaft", {"Ks#Value": v("200"), "alpha#Value": v("1")})
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"alpha = 1 outside \[0, 1\)"):
        read_hopsan(path)


def test_hopsans_c_type_machine_is_a_machine_between_its_port_volumes(tmp_path: Path) -> None:
    """HydraulicMachineC: a Machine (D_m per revolution, C_lm, B_m) between two cavity Volumes of 1.1 V_1,
    1.1 V_2 (what Hopsan's elements hold, their waves filtered with memories two steps old) starting at their
    ports' start pressures, its shaft P3 a torque port. Fed through laminar orifices (Kc) from 100 and
    10 bar and turning an inertia (B = 1), it settles where the orifices' flows are the machine's and the torques
    balance: Kc (p_s1 − p1) = ε D ω + C (p1 − p2) = Kc (p2 − p_s2), ε D (p1 − p2) = (B_m + B) ω."""
    v = _value
    components = [
        ("HydraulicMachineC", "M", {"P1#Pressure": v("3e6", "Pa"), "P2#Pressure": v("2e6", "Pa"),
                                    "eps#Value": v("0.5"), "Beta_e#Value": v("1e9"), "V_1#Value": v("0.001"),
                                    "V_2#Value": v("0.002"), "D_m#Value": v("4e-5"), "C_lm#Value": v("1e-11"),
                                    "B_m#Value": v("0.2")}),
        ("MechanicRotationalInertia", "J", {"J": v("0.1"), "B#Value": v("1"), "k#Value": v("0")}),
        ("MechanicTorqueTransformer", "T", {"T#Value": v("0")}),
        ("HydraulicLaminarOrifice", "O1", {"Kc#Value": v("1e-9")}),
        ("HydraulicLaminarOrifice", "O2", {"Kc#Value": v("1e-9")}),
        ("HydraulicPressureSourceC", "S1", {"p#Value": v("1e7", "Pa")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("1e6", "Pa")}),
    ]
    connections = [("S1.P1", "O1.P2"), ("O1.P1", "M.P1"), ("S2.P1", "O2.P2"), ("O2.P1", "M.P2"),
                   ("J.P2", "M.P3"), ("T.P1", "J.P1")]
    path = tmp_path / "machine.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    sysm = imp.system
    assert sysm["M_V1"].values["V"] == pytest.approx(0.0011) and sysm["M_V2"].values["V"] == pytest.approx(0.0022)
    assert sysm["M_V1"].option("pressure_floor") == "cavity"
    r0 = sysm.simulate(t_eval=[0.0, 1e-9])
    assert r0["M.P1.Pressure"][0] == pytest.approx(3e6) and r0["M.P2.Pressure"][0] == pytest.approx(2e6)
    D, C, Kc, B = 0.5 * 4e-5 / (2.0 * np.pi), 1e-11, 1e-9, 1.2
    # unknowns p1, p2, ω (absolute pressures)
    a = np.array([[Kc + C, -C, D], [-C, Kc + C, -D], [D, -D, -B]])
    rhs = np.array([Kc * 1e7, Kc * 1e6, 0.0])
    p1, p2, omega = np.linalg.solve(a, rhs)
    r = sysm.simulate(t_end=5.0)
    assert r["M.P1.Pressure"][-1] == pytest.approx(p1, rel=1e-6) and r["M.P2.Pressure"][-1] == pytest.approx(p2, rel=1e-6)
    # the inertia's P2 faces the machine's shaft: Hopsan's node speed is the inertia's, minus the shaft's
    assert r["J.P2.AngularVelocity"][-1] == pytest.approx(-omega, rel=1e-6)
    assert r["M.P3.Torque"][-1] == pytest.approx(1.0 * omega, rel=1e-6)


def test_hopsans_gear_shaft_is_a_geared_spring_of_the_stiffness_its_element_converges_to(tmp_path: Path) -> None:
    """MechanicGearShaft: a TorsionalSpring with n_gear = gearRatio and the stiffness Ks/(2 − α) that its
    transmission-line element (a step more delay than its impedance accounts for) converges to; a theta source
    at 2 rad/s through gearRatio -1 turns a damped inertia (B 10) at -2 rad/s (through a plain shaft: +2), the
    torques at its ends opposite."""
    v = _value
    components = [
        ("MechanicThetaSource", "S", {"omega#Value": v("2")}),
        ("MechanicGearShaft", "G", {"gearRatio#Value": v("-1"), "Ks#Value": v("1e4"), "alpha#Value": v("0.5")}),
        ("MechanicRotationalInertia", "J", {"J": v("0.1"), "B#Value": v("10"), "k#Value": v("0")}),
        ("MechanicTorqueTransformer", "T", {"T#Value": v("0")}),
    ]
    connections = [("S.Pmr1", "G.Pmr1"), ("G.Pmr2", "J.P1"), ("J.P2", "T.P1")]
    path = tmp_path / "gear.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    g = imp.system["G"]
    assert g.values["k_rot"] == pytest.approx(1e4 / 1.5) and g.values["n_gear"] == -1.0
    r = imp.system.simulate(t_end=1.0)
    assert r["J.P2.AngularVelocity"][-1] == pytest.approx(-2.0, rel=1e-6)
    assert r["G.Pmr2.Torque"][-1] == pytest.approx(-20.0, rel=1e-6)
    assert r["G.Pmr1.Torque"][-1] == pytest.approx(20.0, rel=1e-6)


def test_a_pressure_controlled_pump_needs_its_reference_port(tmp_path: Path) -> None:
    """HydraulicPressureControlledPump maps to a LoadSensingPump with Hopsan's parameters (q_max at 125 rad/s);
    its PREF left unconnected is refused (Hopsan reads an unconnected port's start value)."""
    circuit = (CIRCUITS / "pressure_controlled_pump.hmf").read_text(encoding="utf-8")
    system = read_hopsan(CIRCUITS / "pressure_controlled_pump.hmf")
    pump = system["Pump"]
    assert pump.values["D"] * pump.values["omega"] == pytest.approx(1.25e-3)
    assert (pump.values["p_dif"], pump.values["tau_v"], pump.values["omega_p1"]) == (28e6, 3e-3, 200.0)
    # its eps is a fraction (QP over q_max ω/125), not a flow
    assert system.aliases["Pump.eps.Value"].unit == ""
    path = tmp_path / "no_ref.hmf"
    path.write_text(circuit.replace('<connect startcomponent="TRef" startport="P1" endcomponent="Pump" '
                                    'endport="PREF"/>', ""), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"Pump \(HydraulicPressureControlledPump\): its reference port PREF"):
        read_hopsan(path)


def test_hopsans_load_sensing_valve_passes_the_loaded_ports_pressure_to_its_line(tmp_path: Path) -> None:
    """[Hopsan2026] FlowControlValves/Hydraulic43LoadSensingValve.hpp: the 4/3 valve with PL at the pressure of A
    while x_v >= 0 and of B otherwise; its line (a volume) settles there."""
    v = _value
    for spool, loaded in (("0.005", 60e5), ("-0.005", 30e5)):
        components = [
            ("Hydraulic43LoadSensingValve", "LS", {"in#Value": v(spool, "m"), "rho#Value": v("890")}),
            ("HydraulicPressureSourceC", "S", {"p#Value": v("1e7", "Pa")}),
            ("HydraulicTankC", "T", {"p": v("1e5", "Pa")}),
            ("HydraulicPressureSourceC", "A", {"p#Value": v("6e6", "Pa")}),
            ("HydraulicPressureSourceC", "B", {"p#Value": v("3e6", "Pa")}),
            ("HydraulicVolumeMultiPort", "Line", {"V#Value": v("1e-5"), "P1#Pressure": v("1e5", "Pa")}),
        ]
        connections = [("LS.PP", "S.P1"), ("LS.PT", "T.P1"), ("LS.PA", "A.P1"), ("LS.PB", "B.P1"),
                       ("LS.PL", "Line.P1")]
        path = tmp_path / "ls.hmf"
        path.write_text(_hmf(components, connections), encoding="utf-8")
        imp = import_hopsan(path)
        assert imp.system["LS"].option("load_sensing") == "port"
        r = imp.system.simulate(t_eval=[0.0, 0.2])
        assert r["LS.PL.Pressure"][-1] == pytest.approx(loaded, rel=1e-9)
        assert r["LS.xv.Value"][-1] == pytest.approx(float(spool), rel=1e-6)


def test_hopsans_reducing_drop_and_pressure_controlled_valves_settle_on_the_relief_valves_law(tmp_path: Path) -> None:
    """[Hopsan2026] Valves/PressureControlValves/HydraulicPressureReducingValve.hpp, HydraulicPressureDropValve.hpp
    and HydraulicPressureControlledValve.hpp: the relief valve's spool, settled at xs = Δp_over/b1 with
    b1 = √p_nom/k_cs + (p_1 - p_2)/(k_cf √p_nom), passing x0 √(p_1 - p_2); Δp_over = p_ref - p_2 (reducing,
    absolute), p_1 - p_2 - p_ref (drop), p_open - p_close - p_ref (controlled, its pilots taking no flow). Each
    valve sits between two fixed pressures, partly open (the hysteresis, 5 bar by default, only delays it)."""
    v = _value
    components = [
        ("HydraulicPressureReducingValve", "RD", {"p_ref#Value": v("5e6", "Pa"), "p_h#Value": v("0", "Pa")}),
        ("HydraulicPressureDropValve", "DR", {"p_ref#Value": v("4.1e6", "Pa")}),
        ("HydraulicPressureControlledValve", "PC", {"p_ref#Value": v("4e6", "Pa"), "p_nom": v("5e6", "Pa")}),
        ("HydraulicPressureSourceC", "S1", {"p#Value": v("1e7", "Pa")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("4.9e6", "Pa")}),
        ("HydraulicPressureSourceC", "S3", {"p#Value": v("4e6", "Pa")}),
        ("HydraulicPressureSourceC", "S4", {"p#Value": v("1e5", "Pa")}),
        ("HydraulicPressureSourceC", "S5", {"p#Value": v("6e6", "Pa")}),
        ("HydraulicPressureSourceC", "S6", {"p#Value": v("1.5e6", "Pa")}),
    ]
    connections = [("RD.P1", "S1.P1"), ("RD.P2", "S2.P1"), ("DR.P1", "S5.P1"), ("DR.P2", "S6.P1"),
                   ("PC.P1", "S1.P1"), ("PC.P2", "S4.P1"), ("PC.P_OPEN", "S5.P1"), ("PC.P_CLOSE", "S6.P1")]
    path = tmp_path / "pressure_valves.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["PC"].option("pilot") == "ports" and imp.system["DR"].option("pilot") == "drop"
    assert imp.system["DR"].values["p_h"] == 5e5 and imp.system["RD"].values["p_h"] == 0.0
    r = imp.system.simulate(t_eval=[0.0, 1.0], accuracy=1e-9)
    for name, p1, p2, over, p_nom in (("RD", 1e7, 4.9e6, 5e6 - 4.9e6, 7e6),
                                      ("DR", 6e6, 1.5e6, 6e6 - 1.5e6 - 4.1e6, 7e6),
                                      ("PC", 1e7, 1e5, 6e6 - 1.5e6 - 4e6, 5e6)):
        dp = p1 - p2
        b1 = np.sqrt(p_nom) / 1e-8 + dp / (1e-8 * np.sqrt(p_nom))
        hysteresis = imp.system[name].values["p_h"] / 2.0  # the spool stops half the band short of xs
        x0 = (over - hysteresis) / b1
        assert 0.0 < x0 < 0.001 / np.sqrt(p_nom)  # partly open
        assert r[f"{name}.Q"][-1] == pytest.approx(x0 * np.sqrt(dp), rel=1e-5)
    assert r["RD.P2.Flow"][-1] == r["RD.Q"][-1]  # Hopsan's flow out of P2: the flow through
    assert r["PC.QX"][-1] == 0.0 and r["PC.QY"][-1] == 0.0


def test_hopsans_pilot_controlled_check_valve_opens_on_its_absolute_pilot_and_then_flows_both_ways(
    tmp_path: Path,
) -> None:
    """[Hopsan2026] Restrictors/HydraulicPilotControlledCheckValve.hpp: open while p_1 + φ p_pilot - p_2 > p_f
    (absolute pressures), then q = K_s √(p_1 - p_2) signed; closed otherwise. Reverse flow (p_2 > p_1) passes only
    while the pilot holds the seat open."""
    v = _value

    def flow(p1: float, p2: float, pilot: float) -> float:
        components = [
            ("HydraulicPilotControlledCheckValve", "CV", {"phi#Value": v("3.5"), "p_f#Value": v("1e6", "Pa"),
                                                          "K_s": v("5e-7")}),
            ("HydraulicPressureSourceC", "S1", {"p#Value": v(repr(p1), "Pa")}),
            ("HydraulicPressureSourceC", "S2", {"p#Value": v(repr(p2), "Pa")}),
            ("HydraulicPressureSourceC", "S3", {"p#Value": v(repr(pilot), "Pa")}),
        ]
        path = tmp_path / "pcv.hmf"
        path.write_text(_hmf(components, [("CV.P1", "S1.P1"), ("CV.P2", "S2.P1"), ("CV.P_PILOT", "S3.P1")]),
                        encoding="utf-8")
        imp = import_hopsan(path)
        assert imp.system["CV"].values["p_crack"] == pytest.approx(1e6 - 3.5 * 101325.0)
        return float(imp.system.simulate(t_eval=[0.0, 0.1])["CV.Q"][-1])

    # p1 - p2 + 3.5 p_pilot (absolute) against 1 MPa
    assert flow(2e6, 1e6, 1e5) == pytest.approx(5e-7 * np.sqrt(1e6), rel=1e-6)  # 1.35 MPa: open forwards
    assert flow(1.2e6, 1e6, 1e5) == 0.0  # 0.55 MPa: closed
    assert flow(1e6, 2e6, 1e5) == 0.0  # reverse, no pilot: held
    assert flow(1e6, 2e6, 6e5) == pytest.approx(-5e-7 * np.sqrt(1e6), rel=1e-6)  # 1.1 MPa with the pilot: released


def test_hopsans_preloaded_orificed_and_pilot_closable_check_valves(tmp_path: Path) -> None:
    """[Hopsan2026] Restrictors/HydraulicCheckValvePreLoaded.hpp (open while p_1 > p_2 + F_s),
    HydraulicCheckValveWithOrifice.hpp (K_s √Δp forwards, K_r √Δp backwards) and
    HydraulicPilotClosableCheckValve.hpp (open while p_1 > p_2 + p_pilot, absolute pressures), each between fixed
    pressures, their flows from the laws by hand."""
    v = _value

    def flows(p1: float, p2: float, pilot: float) -> dict[str, float]:
        components = [
            ("HydraulicCheckValvePreLoaded", "PL", {"F_s#Value": v("5e5", "Pa"), "K_s#Value": v("4e-7")}),
            ("HydraulicCheckValveWithOrifice", "WO", {"K_s#Value": v("4e-7"), "K_r#Value": v("1e-7")}),
            ("HydraulicPilotClosableCheckValve", "PC", {"K_s": v("4e-7")}),
            ("HydraulicPressureSourceC", "S1", {"p#Value": v(repr(p1), "Pa")}),
            ("HydraulicPressureSourceC", "S2", {"p#Value": v(repr(p2), "Pa")}),
            ("HydraulicPressureSourceC", "S3", {"p#Value": v(repr(pilot), "Pa")}),
        ]
        connections = [("PL.P1", "S1.P1"), ("PL.P2", "S2.P1"), ("WO.P1", "S1.P1"), ("WO.P2", "S2.P1"),
                       ("PC.P1", "S1.P1"), ("PC.P2", "S2.P1"), ("PC.P_PILOT", "S3.P1")]
        path = tmp_path / "checks.hmf"
        path.write_text(_hmf(components, connections), encoding="utf-8")
        r = import_hopsan(path).system.simulate(t_eval=[0.0, 0.1])
        total = float(r["WO.Q"][-1] + r["WO_orifice.Q"][-1])
        # Hopsan's flows at the ports, out of the component: the seat's and the orifice's together
        assert float(r["WO_Q1.y"][-1]) == pytest.approx(-total) and float(r["WO_Q2.y"][-1]) == pytest.approx(total)
        return {k: float(r[f"{k}.Q"][-1]) for k in ("PL", "PC")} | {"WO": total}

    f = flows(2e6, 1e6, 5e5)  # forwards 1 MPa: over the pre-load; the pilot (0.5 MPa) below the drop
    assert f["PL"] == pytest.approx(4e-7 * 1e3, rel=1e-6)
    assert f["WO"] == pytest.approx(4e-7 * 1e3, rel=1e-6)
    assert f["PC"] == pytest.approx(4e-7 * 1e3, rel=1e-6)
    f = flows(1.3e6, 1e6, 5e5)  # forwards 0.3 MPa: under the pre-load, and under the pilot
    assert f["PL"] == 0.0 and f["PC"] == 0.0
    assert f["WO"] == pytest.approx(4e-7 * np.sqrt(3e5), rel=1e-6)
    f = flows(1e6, 2e6, 1e5)  # backwards 1 MPa: only the orifice of the orificed valve
    assert f["PL"] == 0.0 and f["PC"] == 0.0
    assert f["WO"] == pytest.approx(-1e-7 * 1e3, rel=1e-6)
def test_hopsans_q_type_pressure_source_holds_the_volume_joined_to_it_at_its_pressure(tmp_path: Path) -> None:
    """HydraulicPressureSourceQ sets the pressure of the C component joined to it (a volume drained by a laminar
    orifice to a tank): in the steady state the node is at p (absolute) and the source delivers Kc (p - p_tank).
    Its p driven by an old file's SignalSource (SignalConstant's former name, its port out) is followed, within
    q/G of the source's conductance."""
    v = _value
    components = [
        ("HydraulicPressureSourceQ", "Q", {"p#Value": v("1e5", "Pa")}),
        ("SignalSource", "C", {"y": v("5e6")}),
        ("HydraulicVolume", "V", {"V": v("1e-3"), "Beta_e": v("1e9"), "P1#Pressure": v("1e5", "Pa")}),
        ("HydraulicLaminarOrifice", "O", {"Kc#Value": v("1e-10")}),
        ("HydraulicTankC", "T", {"p": v("1e5", "Pa")}),
    ]
    connections = [("C.out", "Q.p"), ("Q.P1", "V.P1"), ("V.P2", "O.P1"), ("O.P2", "T.P1")]
    path = tmp_path / "qsource.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert type(imp.system["Q_p"]).__name__ == "PressureSource" and type(imp.system["Q"]).__name__ == "LaminarOrifice"
    r = imp.system.simulate(t_eval=[0.0, 0.01, 0.1])
    assert r["V.P1.Pressure"][-1] == pytest.approx(5e6, rel=1e-7)
    assert r["Q.P1.Pressure"][-1] == pytest.approx(5e6, rel=1e-7)
    assert r["Q.P1.Flow"][-1] == pytest.approx(1e-10 * (5e6 - 1e5), rel=1e-6)
    assert r["C.out.Value"][-1] == 5e6
    del components[1]  # undriven: a tank at its p
    path.write_text(_hmf(components, connections[1:]), encoding="utf-8")
    imp = import_hopsan(path)
    assert type(imp.system["Q_p"]).__name__ == "Tank"
    assert imp.system.simulate(t_eval=[0.0, 0.1])["V.P1.Pressure"][-1] == pytest.approx(1e5, rel=1e-7)


def test_hopsans_q_type_cylinder_is_the_cylinder_with_its_chambers_outside_pushing_its_load(tmp_path: Path) -> None:
    """HydraulicCylinderQ between two C-type pressure sources: m_l ẍ = A_1 p_1 - A_2 p_2 - (B_l + B_p) ẋ - k_l x
    (absolute pressures), so the piston settles at x = (A_1 p_1 - A_2 p_2)/k_l from its P3 start position, or on
    its stop at s_l; it takes A_1 ẋ from P1 and gives A_2 ẋ to P2 (Hopsan's flows count out of it)."""
    v = _value
    cyl = {"A_1#Value": v("2e-4"), "A_2#Value": v("1e-4"), "B_p#Value": v("300"), "B_l#Value": v("200"),
           "k_l#Value": v("1e5"), "m_l": v("2"), "s_l": v("0.5"), "P3#Position": v("0.1")}
    components = [
        ("HydraulicCylinderQ", "Cyl", cyl),
        ("HydraulicPressureSourceC", "S1", {"p#Value": v("1e7", "Pa")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("2e6", "Pa")}),
        ("MechanicPositionSensor", "X", {}),
    ]
    connections = [("Cyl.P1", "S1.P1"), ("Cyl.P2", "S2.P1"), ("Cyl.P3", "X.P1")]
    path = tmp_path / "qcyl.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["Cyl"].option("chambers") == "ports" and imp.system["Cyl_load"].values["m"] == 2.0
    r = imp.system.simulate(t_eval=[0.0, 0.05, 2.0], accuracy=1e-8)
    x_end = (2e-4 * 1e7 - 1e-4 * 2e6) / 1e5
    assert r["Cyl.P3.Position"][0] == pytest.approx(0.1)
    assert r["Cyl.P3.Position"][-1] == pytest.approx(x_end, rel=1e-6)
    speed = r["Cyl.P3.Velocity"][1]
    assert speed < 0.0  # retracting from 0.1 m towards x_end
    assert r["Cyl.P1.Flow"][1] == pytest.approx(-2e-4 * speed, rel=1e-9)
    assert r["Cyl.P2.Flow"][1] == pytest.approx(1e-4 * speed, rel=1e-9)
    cyl["k_l#Value"] = v("1e3")  # x_end = 18 m: the stop at s_l
    path.write_text(_hmf(components, connections), encoding="utf-8")
    r = read_hopsan(path).simulate(t_eval=[0.0, 2.0])
    assert r["Cyl.P3.Position"][-1] == pytest.approx(0.5, abs=2e-5)


def test_hopsans_spring_loaded_piston_is_the_c_cylinder_less_its_spring_force(tmp_path: Path) -> None:
    """HydraulicSpringLoadedPistonC: HydraulicCylinderC's piston with the constant force F_s against it. Between two
    Q-type pressure sources, pushing a damped mass (B) whose stop at 0 it leaves, it reaches the speed
    (A_1 p_1 - A_2 p_2 - F_s)/B (Hopsan's P3 counts it negative, the piston extending)."""
    v = _value
    components = [
        ("HydraulicSpringLoadedPistonC", "P", {"A_1#Value": v("1e-3"), "A_2#Value": v("5e-4"), "s_l#Value": v("10"),
                                               "F_s#Value": v("2000"), "V_1#Value": v("1e-4"), "V_2#Value": v("1e-4"),
                                               "B_p#Value": v("0"), "c_leak#Value": v("0"),
                                               "P1#Pressure": v("4e6", "Pa"), "P2#Pressure": v("1e6", "Pa")}),
        ("HydraulicPressureSourceQ", "Q1", {"p#Value": v("4e6", "Pa")}),
        ("HydraulicPressureSourceQ", "Q2", {"p#Value": v("1e6", "Pa")}),
        ("MechanicTranslationalMass", "M", {"m": v("10"), "B#Value": v("1000"), "k#Value": v("0"),
                                            "x_min#Value": v("0"), "x_max#Value": v("100")}),
    ]
    connections = [("P.P1", "Q1.P1"), ("P.P2", "Q2.P1"), ("P.P3", "M.P1")]
    path = tmp_path / "slp.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    cyl = imp.system["P"]
    assert cyl.values["F_s"] == 2000.0 and cyl.option("pressure_floor") == "check-valve"
    r = imp.system.simulate(t_eval=[0.0, 0.5], accuracy=1e-8)
    force = 1e-3 * 4e6 - 5e-4 * 1e6 - 2000.0
    assert r["P.P3.Velocity"][-1] == pytest.approx(-force / 1000.0, rel=1e-4)
    assert r["P.P3.Force"][-1] == pytest.approx(force, rel=1e-4)


def test_hopsans_fixed_pump_turns_at_the_speed_a_signal_sets(tmp_path: Path) -> None:
    """HydraulicFixedDisplacementPump with n_p driven by a ramp: q = D_p n_p/2π - C_lp (p_2 - p_1) between two
    C-type pressure sources, backwards while n_p < 0 (Pump with speed = input)."""
    v = _value
    components = [
        ("HydraulicFixedDisplacementPump", "P", {"n_p#Value": v("250"), "D_p#Value": v("5e-5"),
                                                 "C_lp#Value": v("1e-12")}),
        ("HydraulicPressureSourceC", "S1", {"p#Value": v("2e5", "Pa")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("1.2e6", "Pa")}),
        ("SignalRamp", "R", {"y_0#Value": v("-10"), "y_A#Value": v("20"), "t_start#Value": v("0"),
                             "t_end#Value": v("10")}),
    ]
    connections = [("P.P1", "S1.P1"), ("P.P2", "S2.P1"), ("R.out", "P.n_p")]
    path = tmp_path / "pump.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["P"].option("speed") == "input"
    r = imp.system.simulate(t_eval=[0.0, 2.5, 5.0, 10.0])
    n = np.array([-10.0, -5.0, 0.0, 10.0])
    np.testing.assert_allclose(r["P.P2.Flow"], 5e-5 * n / (2 * np.pi) - 1e-12 * 1e6, rtol=1e-9, atol=1e-15)



def test_hopsans_valve416_is_four_edges_each_opened_by_its_own_spool_position(tmp_path: Path) -> None:
    """HydraulicValve416 between C-type sources at 100 bar (P), 1 bar (T), 50 bar (A) and 20 bar (B), its four
    spool positions constant: each edge passes Cq √(2/ρ) π Fr Sd limit(X0 + xv, 0, X0 + Xvmax) Δp/(Δp² + plam²)^¼
    (P-A saturated at Xvmax, A-T opened, P-B shut by its overlap, B-T open by its underlap alone); Hopsan's flow at
    each port, out of the valve, is the sum of its two edges'."""
    v = _value
    valve = {"rho": v("860"), "Cq": v("0.67"), "Sd": v("0.01"), "Frpa": v("1"), "Frta": v("0.8"), "Frpb": v("0.6"),
             "Frtb": v("0.5"), "Xpa0": v("0"), "Xta0": v("1e-4"), "Xpb0": v("5e-5"), "Xtb0": v("2e-5"),
             "Xvmax": v("1e-3"), "plam": v("5e4")}
    positions = {"xvpa": "2e-3", "xvta": "3e-4", "xvpb": "-1e-4", "xvtb": "0"}
    components = [
        ("HydraulicValve416", "V", valve),
        *[("HydraulicPressureSourceC", f"S{port}", {"p#Value": v(p, "Pa")})
          for port, p in (("p", "1e7"), ("t", "1e5"), ("a", "5e6"), ("b", "2e6"))],
        *[("SignalConstant", f"C{k}", {"y#Value": v(x)}) for k, x in positions.items()],
    ]
    connections = [*[(f"V.P{port}", f"S{port}.P1") for port in "ptab"], *[(f"C{k}.y", f"V.{k}") for k in positions]]
    path = tmp_path / "valve416.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["V_pb"].values["x_AB"] == -5e-5 and imp.system["V_xpa"].values["upper"] == 1e-3
    r = imp.system.simulate(t_eval=[0.0, 1e-3], method="cvodes")

    def edge(fraction: float, opening: float, dp: float) -> float:
        return 0.67 * np.sqrt(2.0 / 860.0) * np.pi * fraction * 0.01 * max(opening, 0.0) * dp / (dp**2 + 5e4**2) ** 0.25

    q_pa, q_ta = edge(1.0, 1e-3, 1e7 - 5e6), edge(0.8, 4e-4, 5e6 - 1e5)
    q_pb, q_tb = edge(0.6, -5e-5, 1e7 - 2e6), edge(0.5, 2e-5, 2e6 - 1e5)
    assert q_pb == 0.0
    expected = {"Pp": -(q_pa + q_pb), "Pt": q_ta + q_tb, "Pa": q_pa - q_ta, "Pb": q_pb - q_tb}
    for port, q in expected.items():
        assert r[f"V.{port}.Flow"][-1] == pytest.approx(q, rel=1e-9), port

def test_hopsans_four_chamber_piston_is_a_four_chamber_cylinder_pushing_its_mass(tmp_path: Path) -> None:
    """HydraulicFourChamberPiston with its chambers held by Q-type pressure sources at 30, 10, 20 and 5 bar
    (absolute) drives a damped mass (m 100 kg, B 1000 N s/m) from x = 1 m: F = A_1 p_1 − A_2 p_2 + A_3 p_3 − A_4 p_4
    of the absolute pressures, so the mass reaches F/B as F/B (1 − e^(−B t/m)), out of the piston (Hopsan's P5
    position falls). A FourChamberCylinder with Hopsan's names, its position from the retracted end, its chambers
    floored at 0 Pa absolute; use_sl false removes its stops."""
    v = _value
    piston = {"A_1#Value": v("1e-3"), "A_2#Value": v("5e-4"), "A_3#Value": v("2e-4"), "A_4#Value": v("1e-4"),
              "s_l#Value": v("10"), "V_1#Value": v("0.001"), "V_2#Value": v("0.002"), "V_3#Value": v("0.003"),
              "V_4#Value": v("0.004"), "B_p#Value": v("0"), "c_leak13#Value": v("2e-12"),
              "P5#Position": v("-1"), "P1#Pressure": v("3e6", "Pa")}
    components = [
        ("HydraulicFourChamberPiston", "FC", piston),
        ("MechanicTranslationalMass", "M", {"m": v("100"), "B#Value": v("1000"), "k#Value": v("0")}),
        *[("HydraulicPressureSourceQ", f"S{i}", {"p#Value": v(p, "Pa")})
          for i, p in ((1, "3e6"), (2, "1e6"), (3, "2e6"), (4, "5e5"))],
    ]
    connections = [("FC.P5", "M.P1"), *[(f"FC.P{i}", f"S{i}.P1") for i in (1, 2, 3, 4)]]
    path = tmp_path / "four.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    fc = imp.system["FC"]
    assert fc.values["V_4"] == 0.004 and fc.values["c_leak13"] == 2e-12 and fc.values["c_leak12"] == 1e-11
    assert fc.values["p_floor"] == pytest.approx(-101325.0) and fc.values["k_stop"] == 1e9
    assert fc.values["p1_0"] == pytest.approx(3e6 - 101325.0) and fc.values["p2_0"] == pytest.approx(1e5 - 101325.0)
    t = np.array([0.0, 0.05, 0.2, 0.5])
    r = imp.system.simulate(t_eval=t, method="cvodes", accuracy=1e-8)
    v_end = (1e-3 * 3e6 - 5e-4 * 1e6 + 2e-4 * 2e6 - 1e-4 * 5e5) / 1000.0
    np.testing.assert_allclose(r["FC.P5.Velocity"], -v_end * (1.0 - np.exp(-10.0 * t)), rtol=1e-4, atol=1e-6)
    np.testing.assert_allclose(r["FC.P1.Pressure"], 3e6, rtol=1e-6)
    piston["use_sl"] = ("false", "")
    path.write_text(_hmf(components, connections), encoding="utf-8")
    assert import_hopsan(path).system["FC"].values["k_stop"] == 0.0

def test_hopsans_centrifugal_pumps_are_centrifugal_pumps_with_hopsans_slip_term(tmp_path: Path) -> None:
    """HydraulicCentrifugalPump (omegap driven by a signal, 126 rad/s: speed = input) and HydraulicCentrifugalPumpJ (turned by a
    torque of 150 N m at Pmr1), each between 1 and 3 bar (absolute): CentrifugalPump and CentrifugalPumpInertia
    with Hopsan's ρ² slip term and inlet floor; the J pump's port turns at -ω (Hopsan counts outward), its Pin is
    the torque at Pmr1 times ω, and it settles where that torque is the power it gives over ω + 0.001."""
    v = _value
    pars = {"kl#Value": v("0.1"), "b#Value": v("0.03"), "d#Value": v("0.3"), "beta2#Value": v("1.57"),
            "Ap#Value": v("0.001"), "rho#Value": v("860"), "Kcp#Value": v("1e-11"), "Bp#Value": v("0")}
    components = [
        ("HydraulicCentrifugalPump", "CP", {**pars, "omegap#Value": v("157")}),
        ("HydraulicCentrifugalPumpJ", "CJ", {**pars, "Jp#Value": v("0.1")}),
        ("HydraulicPressureSourceC", "I1", {"p#Value": v("1e5", "Pa")}),
        ("HydraulicPressureSourceC", "O1", {"p#Value": v("3e5", "Pa")}),
        ("HydraulicPressureSourceC", "I2", {"p#Value": v("1e5", "Pa")}),
        ("HydraulicPressureSourceC", "O2", {"p#Value": v("3e5", "Pa")}),
        ("SignalConstant", "W", {"y#Value": v("126")}),
        ("MechanicTorqueTransformer", "T", {"T#Value": v("150")}),
    ]
    connections = [("CP.P1", "I1.P1"), ("CP.P2", "O1.P1"), ("W.y", "CP.omegap"),
                   ("CJ.P1", "I2.P1"), ("CJ.P2", "O2.P1"), ("T.P1", "CJ.Pmr1")]
    path = tmp_path / "centrifugal.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    cp, cj = imp.system["CP"], imp.system["CJ"]
    assert (cp.option("slip"), cp.option("inlet"), cj.option("slip"), cj.option("inlet")) == ("hopsan", "floor") * 2
    assert cp.option("speed") == "input" and cp.values["rho"] == 860.0 and cj.values["Jp"] == 0.1
    r = imp.system.simulate(t_eval=[0.0, 4.0], method="cvodes")
    u2, k = 126.0 * 0.15, 0.1 * 860.0 / (2.0 * 1e-6)
    c = 860.0**2 * u2 / (np.pi * 0.3 * 0.03 * np.tan(1.57))
    q = (-c + np.sqrt(c**2 + 4.0 * k * (860.0 * u2**2 - 2e5))) / (2.0 * k)
    assert r["CP.P2.Flow"][-1] == pytest.approx(q, rel=1e-4)
    torque = (2e5 + k * q**2) * q / 126.001
    assert r["CP.torp.Value"][-1] == pytest.approx(torque, rel=1e-4)
    assert r["CP.Pin.Value"][-1] == pytest.approx(126.0 * torque, rel=1e-4)
    omega = -r["CJ.Pmr1.AngularVelocity"][-1]
    assert omega > 100.0
    u2 = omega * 0.15
    c = 860.0**2 * u2 / (np.pi * 0.3 * 0.03 * np.tan(1.57))
    q = (-c + np.sqrt(c**2 + 4.0 * k * (860.0 * u2**2 - 2e5))) / (2.0 * k)
    assert r["CJ.P2.Flow"][-1] == pytest.approx(q, rel=1e-4)
    assert (2e5 + k * q**2) * q / (omega + 0.001) == pytest.approx(150.0, rel=1e-4)
    assert r["CJ.Pin.Value"][-1] == pytest.approx(150.0 * omega, rel=1e-6)

def test_hopsans_directional_check_valve_checks_until_its_spool_passes_half_then_opens_both_ways(tmp_path: Path) -> None:
    """Hydraulic22DirectionalCheckValve between 10 bar and 50 bar (absolute): checked, no flow back from P2; with
    ``in`` stepped to 1 its spool (1/(s²/ω² + 2 s/ω + 1) of the step) passes 0.5 at ω t = 1.678 and the valve
    passes Kv_open √(p_2 - p_1) from P2 to P1. Kv gives the bores (C_d 0.67, ρ 870 kg/m³); F_s the cracking."""
    v = _value
    valve = {"omega_h": v("100"), "delta_h": v("1"), "Kv_open#Value": v("4e-8"), "Kv_check#Value": v("2e-8"),
             "F_s#Value": v("3e5"), "out#Value": v("0")}
    components = [
        ("Hydraulic22DirectionalCheckValve", "V", valve),
        ("HydraulicPressureSourceC", "S1", {"p#Value": v("1e6", "Pa")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("5e6", "Pa")}),
        ("SignalStep", "U", {"y_0#Value": v("0"), "y_A#Value": v("1"), "t_step#Value": v("0.1")}),
    ]
    connections = [("V.P1", "S1.P1"), ("V.P2", "S2.P1"), ("U.out", "V.in")]
    path = tmp_path / "dcv.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    cv = imp.system["V"]
    assert cv.option("pilot") == "open" and cv.values["p_crack"] == 3e5
    area = lambda k: k / (0.67 * np.sqrt(2.0 / 870.0))  # noqa: E731
    assert np.pi * cv.values["d_open"] ** 2 / 4 == pytest.approx(area(4e-8)) and np.pi * cv.values["d"] ** 2 / 4 == pytest.approx(area(2e-8))
    t_half = 0.1 + 1.678347 / 100.0  # (1 + ω t) e^(-ω t) = 0.5
    r = imp.system.simulate(t_eval=[0.0, 0.1, t_half - 1e-4, t_half + 1e-4, 0.3])
    assert list(r["V.P1.Flow"][:3]) == [0.0, 0.0, 0.0]
    assert r["V.P1.Flow"][3] == pytest.approx(4e-8 * np.sqrt(4e6), rel=1e-4)
    assert r["V.out.Value"][-1] == pytest.approx(1.0, abs=1e-6)


def test_hopsans_over_centre_and_counterbalance_valves_open_as_their_pilots_add_to_the_load(tmp_path: Path) -> None:
    """HydraulicOverCenterValve: the relief valve's spool opened by p_1 + a_ratio p_control over p_ref (absolute),
    K = over/(C_s + C_f Δp), Q = K √Δp, its xv that K; HydraulicCounterBalanceValveG: the G relief valve's spool
    balance with kappa p_3 added, B_v ẋ = A_v (p_1 - p_2 + kappa p_3 - pref) - (ks + 2 Cq w cos φ Δp) x, settling
    where the right side vanishes. Neither has a check valve (held both ways while closed)."""
    v = _value
    oc = {"p_ref#Value": v("2.5e7"), "p_h#Value": v("0"), "a_ratio#Value": v("4"), "tao": v("0.005"),
          "k_cs": v("1e-8"), "k_cf": v("1e-8"), "q_nom": v("0.01"), "p_nom": v("7e6")}
    cb = {"pref#Value": v("2e6"), "rho#Value": v("860"), "Dv#Value": v("0.01"), "frac#Value": v("0.1"),
          "kappa#Value": v("0.5"), "Bv#Value": v("100"), "Xvmax#Value": v("0.003"), "Cq#Value": v("0.67"),
          "phi#Value": v("0.5"), "ks#Value": v("1e5"), "p0#Value": v("1e5"), "xv#Value": v("0")}
    components = [
        ("HydraulicOverCenterValve", "OC", oc),
        ("HydraulicCounterBalanceValveG", "CB", cb),
        ("HydraulicPressureSourceC", "L1", {"p#Value": v("1.5e7", "Pa")}),
        ("HydraulicPressureSourceC", "X1", {"p#Value": v("3e6", "Pa")}),
        ("HydraulicTankC", "T1", {"p": v("1e5", "Pa")}),
        ("HydraulicPressureSourceC", "L2", {"p#Value": v("2.1e6", "Pa")}),
        ("HydraulicPressureSourceC", "X2", {"p#Value": v("1e6", "Pa")}),
        ("HydraulicTankC", "T2", {"p": v("1e5", "Pa")}),
    ]
    connections = [("OC.P1", "L1.P1"), ("OC.P2", "T1.P1"), ("OC.P_CONTROL", "X1.P1"),
                   ("CB.P1", "L2.P1"), ("CB.P2", "T2.P1"), ("CB.P3", "X2.P1")]
    path = tmp_path / "cbv.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    for name, pilot in (("OC", "inlet"), ("CB", "drop")):
        assert imp.system[name].option("check") == "none" and imp.system[name].option("pilot") == pilot
    r = imp.system.simulate(t_eval=[0.0, 1.0], accuracy=1e-9)
    dp = 1.5e7 - 1e5
    over = 1.5e7 + 4 * 3e6 - 2.5e7  # 20 bar
    K = over / (np.sqrt(7e6) / 1e-8 + dp / (1e-8 * np.sqrt(7e6)))
    assert r["OC.xv.Value"][-1] == pytest.approx(K, rel=1e-6)
    assert r["OC.P2.Flow"][-1] == pytest.approx(K * np.sqrt(dp), rel=1e-5)
    dp2 = 2.1e6 - 1e5
    w, av = np.pi * 0.01 * 0.1 * np.sin(0.5), np.pi * 0.01**2 / 4
    x = av * (dp2 + 0.5 * 1e6 - 2e6) / (1e5 + 2 * 0.67 * w * np.cos(0.5) * dp2)
    assert r["CB.xv.Value"][-1] == pytest.approx(x, rel=1e-4)
    q = 0.67 * w * x * np.sqrt(2 / 860) * dp2 / (dp2**2 + 1e10) ** 0.25
    assert r["CB.P2.Flow"][-1] == pytest.approx(q, rel=1e-4)


def test_hopsans_piston_with_mass_load_leaks_between_its_ports_and_stops_at_xmin_xmax(tmp_path: Path) -> None:
    """HydraulicPistonMload: mL ẍ = A1 p_1 - A2 p_2 - f - (bL + bp) ẋ within [xmin, xmax], q_1 = -A1 ẋ - Cip
    (p_1 - p_2): between two C-type pressure sources it accelerates at (A1 p_1 - A2 p_2)/mL from its start position
    and rests on xmax, where only the leakage flows; its fc (declared, in no equation of Hopsan's) is ignored."""
    v = _value
    piston = {"A1#Value": v("2e-3"), "A2#Value": v("1e-3"), "SL#Value": v("0.4"), "Cip#Value": v("1e-12"),
              "bp#Value": v("0"), "mL#Value": v("100"), "bL#Value": v("0"), "fc#Value": v("10"), "bfc#Value": v("1"),
              "xmin#Value": v("0"), "xmax#Value": v("0.3"), "Pmp#Position": v("0.1")}
    components = [
        ("HydraulicPistonMload", "P", piston),
        ("HydraulicPressureSourceC", "S1", {"p#Value": v("2e6", "Pa")}),
        ("HydraulicPressureSourceC", "S2", {"p#Value": v("1e6", "Pa")}),
        ("MechanicPositionSensor", "X", {}),
    ]
    connections = [("P.P1", "S1.P1"), ("P.P2", "S2.P1"), ("P.Pmp", "X.P1")]
    path = tmp_path / "pml.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    imp = import_hopsan(path)
    assert imp.system["P"].values["C_Li"] == 1e-12 and imp.system["P_load"].values["x_max"] == 0.3
    r = imp.system.simulate(t_eval=[0.0, 0.02, 1.0], accuracy=1e-9)
    a = (2e-3 * 2e6 - 1e-3 * 1e6) / 100.0
    assert r["P.Pmp.Position"][1] == pytest.approx(0.1 + a * 0.02**2 / 2, rel=1e-6)
    assert r["P.P1.Flow"][1] == pytest.approx(-2e-3 * a * 0.02 - 1e-12 * 1e6, rel=1e-6)
    assert r["P.Pmp.Position"][-1] == pytest.approx(0.3, abs=1e-5)
    assert r["P.P1.Flow"][-1] == pytest.approx(-1e-12 * 1e6, rel=1e-3)


def test_a_pressure_sensor_shows_the_pressure_of_its_node(tmp_path: Path) -> None:
    """Hopsan's pressure sensor gives its node's absolute pressure: its output (the number its blocks are fed) is
    the node's pressure plus the atmosphere, and shown in any pressure unit it reads as the node's own pressure
    (declared as a gauge pressure, 'Pa', it was shown one atmosphere too high in Pa_abs, bar or psi)."""
    components = [("HydraulicPressureSourceC", "S", {"p#Value": ("5e6", "Pa")}), ("HydraulicFlowSourceQ", "Q", {}),
                  ("HydraulicPressureSensor", "PS", {}), ("SignalSink", "Scope", {})]
    connections = [("S.P1", "Q.P1"), ("PS.P1", "Q.P1"), ("PS.out", "Scope.in")]
    path = tmp_path / "sensor.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    r = read_hopsan(path).simulate(t_eval=[0.0, 0.1])
    assert r["PS.out.Value"][-1] == pytest.approx(5e6)  # Hopsan's number, absolute
    for unit in ("Pa_abs", "bar", "psi"):
        assert r.get("PS.out.Value", unit)[-1] == pytest.approx(r.get("S.P1.Pressure", unit)[-1], rel=1e-9), unit


def test_two_names_that_would_name_the_same_variables_are_refused(tmp_path: Path) -> None:
    """'Ctl-x' and 'Ctl_x' both give variables 'Ctl_x.out.Value': one of Hopsan's variables was lost and the
    other's alias named the wrong block, without a word (issue 37's review)."""
    components = [("SignalConstant", "Ctl-x", {"y#Value": ("1", "")}), ("SignalGain", "Ctl_x", {"k#Value": ("2", "")}),
                  ("SignalSink", "Scope", {})]
    connections = [("Ctl-x.y", "Ctl_x.in"), ("Ctl_x.out", "Scope.in")]
    path = tmp_path / "clash.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"'Ctl-x' and 'Ctl_x' would both name their variables 'Ctl_x'"):
        read_hopsan(path)
