"""Hopsan model files (hydroservo.io.hopsan): structure, subsystems, parameter expressions, hostile files.

The fixtures are written here in Hopsan's format (hmfversion 0.4, as Hopsan 2.x writes it), so that the tests
need no file of Hopsan's. With ``HOPSAN_SOURCE`` set to a clone of Hopsan's repository, every model file under
its ``Models/`` is read as well.
"""

from __future__ import annotations

import math
import os
import random
import time
from pathlib import Path

import pytest

from hydroservo.errors import ModelFileError
from hydroservo.io.hopsan import MAX_EXPRESSION, evaluate, read_hmf


def _component(typename: str, name: str, params: dict[str, tuple[str, str]], cqs: str = "S") -> str:
    rows = "".join(f'<parameter type="double" name="{k}" value="{v}" unit="{u}"/>' for k, (v, u) in params.items())
    return (f'<component subtypename="" name="{name}" typename="{typename}" cqstype="{cqs}">'
            f"<parameters>{rows}</parameters><hopsangui><pose x='0' y='0'/></hopsangui></component>")


def _connect(a: str, pa: str, b: str, pb: str) -> str:
    return f'<connect startcomponent="{a}" startport="{pa}" endcomponent="{b}" endport="{pb}"/>'


SERVO = (
    '<system subtypename="" name="Servo1" typename="Subsystem" cqstype="Q">'
    '<parameters><parameter type="double" name="PGain" value="0.003"/></parameters>'
    "<objects>"
    + _component("SignalGain", "Gain", {"k#Value": ("PGain*2", "")})
    + _component("Hydraulic43Valve", "Valve", {"x_vmax#Value": ("Stroke", "m"), "d#Value": ("0.01", "m")}, "Q")
    + '<systemport name="In" typename="HopsanGUIContainerPort"/>'
    + '<systemport name="Supply" typename="HopsanGUIContainerPort"/>'
    + "</objects><connections>"
    + _connect("In", "In", "Gain", "in")
    + _connect("Gain", "out", "Valve", "in")
    + _connect("Valve", "PP", "Supply", "Supply")
    + "</connections></system>"
)

MODEL = (
    '<?xml version="1.0" encoding="UTF-8"?>\n'
    '<hopsanmodelfile hmfversion="0.4" hopsanguiversion="2.20" hopsancoreversion="2.20">'
    "<info><description>Two levels, as Hopsan writes them.</description></info>"
    '<system subtypename="" name="Top" typename="Subsystem">'
    '<simulationtime stop="3" timestep="0.0001" start="0" inherit_timestep="true"/>'
    '<parameters><parameter type="double" name="Stroke" value="1e-3" unit="m"/></parameters>'
    "<objects>"
    + _component("SignalStep", "Step", {"y_A#Value": ("0.5", ""), "t_step#Value": ("1", "s")})
    + _component("HydraulicPressureSourceC", "Source", {"p#Value": ("2e7", "Pa")}, "C")
    + _component("SignalSink", "Scope", {})
    + SERVO
    + "</objects><connections>"
    + _connect("Step", "out", "Servo1", "In")
    + _connect("Source", "P1", "Servo1", "Supply")
    + _connect("Step", "out", "Scope", "in")
    + _connect("Servo1", "In", "Scope", "in")
    + "</connections></system></hopsanmodelfile>"
)


def _file(tmp_path: Path, text: str, name: str = "model.hmf") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_components_parameters_and_settings_are_read(tmp_path: Path) -> None:
    model = read_hmf(_file(tmp_path, MODEL))
    assert (model.name, model.start, model.stop, model.timestep) == ("Top", 0.0, 3.0, 1e-4)
    assert model.description == "Two levels, as Hopsan writes them."
    assert [c.full_name for c in model.components] == ["Step", "Source", "Scope", "Servo1.Gain", "Servo1.Valve"]
    assert model.types()["Hydraulic43Valve"] == 1
    valve = model.component("Servo1.Valve")
    assert valve.path == ("Servo1",) and valve.cqs == "Q"
    stroke = valve.parameters["x_vmax#Value"]
    assert (stroke.text, stroke.unit, stroke.value) == ("Stroke", "m", 1e-3)  # a parameter of the top system
    assert model.component("Servo1.Gain").parameters["k#Value"].value == pytest.approx(0.006)  # of its own
    assert model.parameters["Stroke"].value == 1e-3


def test_subsystems_are_flattened_through_their_ports(tmp_path: Path) -> None:
    groups = {frozenset(p) for p in read_hmf(_file(tmp_path, MODEL)).connections}
    # through the subsystem's port In: the step, the gain inside, and the scope reading the port outside
    assert frozenset({"Step.out", "Servo1.Gain.in", "Scope.in"}) in groups
    assert frozenset({"Source.P1", "Servo1.Valve.PP"}) in groups  # an oil line through Supply
    assert frozenset({"Servo1.Gain.out", "Servo1.Valve.in"}) in groups
    assert frozenset({"Step.out", "Scope.in"}) in groups  # a direct connection stays a pair
    assert len(groups) == 4


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;">]>'
         "<hopsanmodelfile>&lol2;</hopsanmodelfile>", "refused"),
        ('<?xml version="1.0"?><!DOCTYPE x [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>'
         "<hopsanmodelfile>&xxe;</hopsanmodelfile>", "refused"),
        ('<?xml version="1.0"?><!DOCTYPE hopsanmodelfile SYSTEM "http://example.com/x.dtd"><hopsanmodelfile/>',
         "refused"),
        (MODEL[: len(MODEL) // 2], "not well-formed"),
        ("<html><body/></html>", "expected <hopsanmodelfile>"),
        ('<hopsanmodelfile hmfversion="0.4"/>', "no <system>"),
        (MODEL.replace('value="PGain*2"', 'value="__import__(os)"'), "function __import__\\(\\) is not read"),
        (MODEL.replace('value="PGain*2"', 'value="PGain;import os"'), "cannot read"),
        (MODEL.replace('value="PGain*2"', 'value="Nope*2"'), "no system parameter 'Nope'"),
        (MODEL.replace('stop="3"', 'stop="-1"'), "expected stop > start"),
        (MODEL.replace('name="Gain"', 'name=""'), "without a name"),
    ],
)
def test_hostile_and_malformed_files_are_refused_clearly(tmp_path: Path, text: str, message: str) -> None:
    path = _file(tmp_path, text)
    with pytest.raises(ModelFileError, match=message) as caught:
        read_hmf(path)
    assert str(path) in str(caught.value)


def test_deep_nesting_is_refused(tmp_path: Path) -> None:
    inner = _component("SignalGain", "G", {"k#Value": ("1", "")})
    for k in range(40):
        inner = f'<system name="S{k}" typename="Subsystem"><objects>{inner}</objects></system>'
    text = f'<hopsanmodelfile><system name="Top"><objects>{inner}</objects></system></hopsanmodelfile>'
    with pytest.raises(ModelFileError, match="nested more than 32 deep"):
        read_hmf(_file(tmp_path, text))


def test_missing_and_folder_paths(tmp_path: Path) -> None:
    with pytest.raises(ModelFileError, match="cannot read"):
        read_hmf(tmp_path / "none.hmf")
    with pytest.raises(ModelFileError, match="is a folder"):
        read_hmf(tmp_path)


def test_expressions_follow_the_grammar_and_nothing_else() -> None:
    names = {"A": 2.0, "Cyl.A1": 1e-3}
    assert evaluate("1 + 2*3", names) == 7.0
    assert evaluate("2^3^2", names) == 512.0  # right-associative
    assert evaluate("-A^2", names) == -4.0 and evaluate("2^-1", names) == 0.5
    assert evaluate("(A + 1)/4", names) == 0.75
    assert evaluate("Cyl.A1*1e3", names) == pytest.approx(1.0)
    for text, message in [("sin(1)", "function sin"), ("A +", "expected a number"), ("(1", "not closed"),
                          ("1/0", "division by zero"), ("9^9^9", "not finite"), ("1 2", "unexpected"),
                          ("x" * (MAX_EXPRESSION + 1), "characters"), ("(" * 30 + "1" + ")" * 30, "nested more"),
                          ("a;b", "cannot read"), ("", "empty"), ("(-8)^0.5", "fractional power"),
                          ("2^-1 + B", "no system parameter"), ("__class__", "no system parameter")]:
        with pytest.raises(ValueError, match=message):
            evaluate(text, names)


def test_random_expressions_end_in_a_number_or_a_clear_refusal() -> None:
    # fuzz: any text of the grammar's characters and others ends quickly, in a finite number or a ValueError
    rng = random.Random(26)
    alphabet = "0123456789.eE+-*/^() A_x,;'\"\\\n"
    start = time.perf_counter()
    for _ in range(3000):
        text = "".join(rng.choice(alphabet) for _ in range(rng.randint(0, 40)))
        try:
            value = evaluate(text, {"A": 1.5, "A_x": -2.0})
        except ValueError:
            continue
        assert math.isfinite(value)
    assert time.perf_counter() - start < 10.0


def test_random_bytes_never_crash_the_reader(tmp_path: Path) -> None:
    rng = random.Random(5)
    for k in range(60):
        cut = rng.randint(0, len(MODEL))
        text = MODEL[:cut] + "".join(chr(rng.randint(32, 126)) for _ in range(rng.randint(0, 20))) + MODEL[cut:]
        path = _file(tmp_path, text, f"m{k}.hmf")
        try:
            read_hmf(path)
        except ModelFileError:
            pass


@pytest.mark.skipif(not os.environ.get("HOPSAN_SOURCE"), reason="HOPSAN_SOURCE: a clone of Hopsan's repository")
def test_every_model_file_of_hopsan_is_read() -> None:
    files = sorted(Path(os.environ["HOPSAN_SOURCE"], "Models").rglob("*.hmf"))
    assert len(files) > 100
    for path in files:
        model = read_hmf(path)
        assert model.components, path


def test_names_may_hold_a_slash_and_a_connection_must_name_what_is_there(tmp_path: Path) -> None:
    """Hopsan names a valve "4/3 Directional Valve"; a connection naming a component the system lacks is refused
    (it was dropped silently)."""
    text = MODEL.replace('name="Source"', 'name="4/3 Source"').replace('startcomponent="Source"', 'startcomponent="4/3 Source"')
    model = read_hmf(_file(tmp_path, text))
    assert "4/3 Source" in [c.full_name for c in model.components]
    assert any("4/3 Source.P1" in group for group in model.connections)
    ghost = MODEL.replace('startcomponent="Step" startport="out" endcomponent="Scope"', 'startcomponent="Ghost" startport="out" endcomponent="Scope"')
    with pytest.raises(ModelFileError, match=r"names 'Ghost', which is no component, subsystem or port"):
        read_hmf(_file(tmp_path, ghost, "ghost.hmf"))


@pytest.mark.parametrize(("core", "renamed"), [("0.6.x_r5334", True), ("0.5.3", True), ("0.7.x_r8296", False),
                                               ("2.24.0", False)])
def test_files_of_hopsan_before_0_6_name_port_variables_with_colons_as_its_loader_reads_them(
    tmp_path: Path, core: str, renamed: bool
) -> None:
    """Hopsan's loader (HmfLoader.cpp, updateOldModelFileParameter) reads P1::Pressure as P1#Pressure, P1#CharImp
    as P1#CharImpedance and omega_p,1 as omega_p1 in files of core versions before 0.6.0 and the 0.6.x snapshots
    (HydraulicShuttleValveTest.hmf and HydraulicPressureControlPumpTest.hmf are some)."""
    path = tmp_path / "old.hmf"
    path.write_text(
        f'<?xml version="1.0"?><hopsanmodelfile hmfversion="0.4" hopsancoreversion="{core}">'
        '<system name="old" typename="Subsystem"><objects>'
        '<component typename="HydraulicPressureSourceC" name="S"><parameters>'
        '<parameter name="p::Value" value="1e6" type="double" unit="Pa"/>'
        '<parameter name="P1::CharImp" value="0" type="double" unit=""/>'
        '<parameter name="omega_p,1" value="200" type="double" unit=""/></parameters></component>'
        "</objects><connections/></system></hopsanmodelfile>",
        encoding="utf-8",
    )
    (source,) = read_hmf(path).components
    assert ("p#Value" in source.parameters) is renamed and ("p::Value" in source.parameters) is not renamed
    assert ("P1#CharImpedance" in source.parameters) is renamed and ("omega_p1" in source.parameters) is renamed
