"""Close matches for every unknown name: commands, options, models, component types, components, parameters,
signals, methods. Each refusal stays one line with exit code 2, prefixed once by ``hydroservo: error:``."""

from __future__ import annotations

import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.cli import main
from hydroservo.errors import HydroservoError, close_names, did_you_mean


@pytest.fixture
def cli(capsys: pytest.CaptureFixture[str]):
    """``hydroservo ARGV`` in-process, argument errors (argparse exits) included: (exit code, stdout, stderr)."""

    def run(*argv: str) -> tuple[int, str, str]:
        try:
            code = main(list(argv))
        except SystemExit as exc:
            code = exc.code
        out = capsys.readouterr()
        return code, out.out, out.err

    return run


def test_close_names_find_typos_and_other_cases_and_nothing_far() -> None:
    assert close_names("cylinder", ["Cylinder", "Mass", "Volume"]) == ["Cylinder"]
    assert close_names("flight-simulatr", ["flight-simulator", "position-servo"]) == ["flight-simulator"]
    assert close_names("FLIGHT-SIMULATR", ["flight-simulator", "position-servo"]) == ["flight-simulator"]
    assert close_names("xyz", ["load", "cyl", "valve"]) == []
    assert did_you_mean("lod", ["load", "cyl"]) == " (did you mean 'load'?)"
    assert did_you_mean("xyz", ["load", "cyl"]) == ""


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["simulat", "flight-simulator"], "invalid choice: 'simulat'"),
        (["simulate", "flight-simulator", "--jsn"], "unrecognized arguments: --jsn (did you mean '--json'?)"),
        (["export-fmu", "flight-simulator", "--methd", "rk4"], "(did you mean '--method'?)"),
        (["simulate", "flight-simulatr"], "(did you mean 'flight-simulator'?)"),
        (["describe", "cylinder"], "component type 'cylinder': unknown (did you mean 'Cylinder'?)"),
        (["describe", "flight-simulator"], "'flight-simulator' is a built-in model, not a component type"),
        (["simulate", "flight-simulator", "--set", "lod.W=3"], "no component 'lod' (did you mean 'load'?)"),
        (["simulate", "flight-simulator", "--set", "load.WW=3"], "no parameter 'WW' (did you mean 'W'?)"),
        (["simulate", "flight-simulator", "--method", "rodas"], "(did you mean 'rodas3'?)"),
    ],
    ids=["command", "option", "option-of-another-command", "model", "component-type", "model-as-component-type",
         "component", "parameter", "method"],
)
def test_a_mistyped_name_gets_its_closest_matches(argv: list[str], expected: str, cli) -> None:
    code, out, err = cli(*argv)
    assert code == 2 and out == "" and expected in err, err
    assert err.count("hydroservo: error:") == 1 and "error: hydroservo" not in err and err.count("\n") == 1


def test_the_help_pointed_to_is_the_subcommand_meant(cli) -> None:
    _, _, err = cli("simulate", "flight-simulator", "--jsn")
    assert err.endswith("(see hydroservo simulate --help)\n")
    _, _, err = cli("simulate")
    assert err.startswith("hydroservo: error: simulate: the following arguments are required")


def test_the_api_suggests_signals_components_and_parameters() -> None:
    s = hs.System("spring", t_end=0.1)
    s.add(c.Mass("load", m=2.0, k_spring=800.0, x0=0.01, incline=0.0))
    with pytest.raises(HydroservoError, match=r"no component 'lod' in system 'spring' \(did you mean 'load'\?\)"):
        s["lod"]
    with pytest.raises(HydroservoError, match=r"unknown parameter of Mass \(did you mean 'k_spring' or 'x_spring'\?\)"):
        s.set("load.k_sprng", 1.0)
    result = s.simulate(n_points=11, method="cvodes")
    with pytest.raises(HydroservoError, match=r"no signal 'load.xx' .*\(did you mean 'load.x'"):
        result["load.xx"]


# -- issue 37: the names and units of every option get their closest matches -----------------------------------
@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["linearize", "robot-arm", "--outputs", "load.vv"],
         "--outputs 'load.vv': not a state, output or alias of 'robot-arm' (did you mean 'load.v'"),
        (["linearize", "robot-arm", "--inputs", "command.amplitud"], "(did you mean 'command.amplitude'"),
        (["linearize", "robot-arm", "--free", "load.xx"], "--free 'load.xx': not a state of 'robot-arm' (did you mean 'load.x'"),
        (["linearize", "robot-arm", "--at", "load.xx=0.01"], "--at 'load.xx': not a state of 'robot-arm' (did you mean 'load.x'"),
        (["sensitivity", "robot-arm", "--vary", "lod.m=10..20"], "no component 'lod' (did you mean 'load'?)"),
        (["sensitivity", "robot-arm", "--vary", "load.m=10..20", "--metric", "peek(load.x)"],
         "unknown kind 'peek' (did you mean 'peak'?)"),
        (["sensitivity", "robot-arm", "--vary", "load.m=10..20", "--metric", "peak(load.xx)"],
         "'load.xx' is not a state, output or alias of the model (did you mean 'load.x'"),
        (["sensitivity", "robot-arm", "--method", "oat", "--vary", "load.m=10..20", "--signals", "load.xx"],
         "signal 'load.xx': not a state, output or alias of 'robot-arm' (did you mean 'load.x'"),
        (["ladder", "robot-arm", "--free", "load.xx"], "free = 'load.xx' is not a state of 'robot-arm' (did you mean 'load.x'"),
        (["simulate", "robot-arm", "--units", "p=barr"], "unknown unit 'barr' (did you mean 'bar'"),
        (["simulate", "robot-arm", "--set", "load.m=20 kgg"], "unknown unit 'kgg' (did you mean 'kg'?)"),
    ],
    ids=["linearize-outputs", "linearize-inputs", "linearize-free", "linearize-at", "sensitivity-vary",
         "sensitivity-metric-kind", "sensitivity-metric-signal", "sensitivity-signals", "ladder-free", "units-unit",
         "set-unit"],
)
def test_every_name_and_unit_option_suggests(argv: list[str], expected: str, cli) -> None:
    code, out, err = cli(*argv)
    assert code == 2 and out == "" and expected in err, err
    assert err.count("hydroservo: error:") == 1 and err.count("\n") == 1


def test_an_unknown_unit_is_called_so_with_its_closest_units() -> None:
    result = hs.load_model("robot-arm").simulate(t_end=0.01, n_points=3)
    with pytest.raises(HydroservoError, match=r"signal 'cyl.pA' of 'robot-arm': unknown unit 'barr' \(did you mean 'bar'"):
        result.get("cyl.pA", "barr")
    with pytest.raises(HydroservoError, match=r"is in Pa: cannot show it in 'mm', a unit of another dimension"):
        result.get("cyl.pA", "mm")
