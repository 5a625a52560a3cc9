"""The general commands: ``hydroservo models``, ``simulate``, ``export``, ``validate``, and bad input."""

from __future__ import annotations

import json

import pytest


def test_cli_simulate_json(tmp_path, cli) -> None:
    code, out, _ = cli(
        "simulate", "flight-simulator", "--set", "load.W=3000 lbf", "--t-end", "0.5", "--out", str(tmp_path), "--json"
    )
    assert code == 0
    data = json.loads(out)
    # the model file speaks psi and in ([model] units): so do the JSON and the CSV
    assert data["signals"]["p2"]["unit"] == "psi" and data["signals"]["y"]["unit"] == "in"
    assert 1000 < data["signals"]["p2"]["max"] < 2000  # psi, not Pa
    assert "nsteps" in data["solver"] and data["wall_time_s"] > 0
    assert (tmp_path / "flight-simulator.csv").exists() and (tmp_path / "flight-simulator.png").exists()
    first = (tmp_path / "flight-simulator.csv").read_text(encoding="utf-8-sig").splitlines()[0]
    assert "y [in]" in first and "p2 [psi]" in first and "valve.QA [in³/s]" in first


def test_cli_simulate_json_alone_writes_nothing_and_write_picks_the_files(tmp_path, cli, monkeypatch) -> None:
    # --json is for programs: no folder unless asked (--out or --write); --write chooses the files.
    monkeypatch.chdir(tmp_path)
    code, out, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--json")
    assert code == 0 and json.loads(out)["files"] == {} and list(tmp_path.iterdir()) == []
    code, out, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--json", "--write", "csv,mat", "--out", "r")
    assert code == 0 and sorted(json.loads(out)["files"]) == ["csv", "mat"]
    assert sorted(p.name for p in (tmp_path / "r").iterdir()) == ["flight-simulator.csv", "flight-simulator.mat"]
    code, _, err = cli("simulate", "flight-simulator", "--write", "csv,xls", "--out", "s")
    assert code == 2 and "--write 'csv,xls'" in err and "csv, png, mat" in err and not (tmp_path / "s").exists()


def test_cli_simulate_csv_reads_back_as_the_result(tmp_path, cli) -> None:
    import pandas as pd

    import hydroservo as hs
    from hydroservo.io.results import read_csv

    code, _, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--points", "51", "--write", "csv", "--out", str(tmp_path))
    assert code == 0
    path = tmp_path / "flight-simulator.csv"
    assert path.read_bytes().startswith(b"\xef\xbb\xbf")  # the mark by which spreadsheets read in³/s right
    table = pd.read_csv(path)  # pandas drops the mark
    result = hs.load_model("flight-simulator").simulate(t_end=0.2, n_points=51)
    shown = result.shown_units()
    assert shown["p2"] == "psi" and shown["valve.QA"] == "in^3/s" and shown["amp.i"] == "mA"
    assert list(table.columns) == ["t [s]", *(f"{n} [{hs.units.si_unit(u)}]" for n, u in shown.items())]
    back = read_csv(path)  # in SI again, whatever units the file is in
    for name in ("y", "p2", "spool.xv", "valve.QA"):  # ten significant digits
        column = next(c for c in table.columns if c.startswith(f"{name} ["))
        assert table[column].to_numpy() == pytest.approx(result.get(name, shown[name]), rel=1e-9, abs=1e-300)
        assert back[name] == pytest.approx(result[name], rel=1e-9, abs=1e-300)
    assert back.shown_units()["p2"] == "psi"  # and shown in the file's units


def test_cli_simulate_units_si_and_ascii(tmp_path, cli) -> None:
    code, out, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--json", "--units", "p=bar, Q=L/min, y=mm")
    signals = json.loads(out)["signals"]
    assert (signals["p2"]["unit"], signals["cyl.pB"]["unit"], signals["valve.QA"]["unit"]) == ("bar", "bar", "L/min")
    assert (signals["y"]["unit"], signals["load.x"]["unit"]) == ("mm", "in")  # y alone; the other lengths stay in
    code, out, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--json", "--si")
    assert json.loads(out)["signals"]["p2"]["unit"] == "Pa"
    code, out, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--write", "csv", "--ascii", "--out", str(tmp_path))
    raw = (tmp_path / "flight-simulator.csv").read_bytes()
    assert raw.isascii() and b"valve.QA [in^3/s]" in raw and b"cyl.pA [psi]" in raw
    text = out.splitlines()
    assert text[1].split() == ["signal", "unit", "final", "min", "max"] and len(text) < 14  # the main signals
    assert "more signals in the CSV" in out
    code, out, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--write", "none", "--all")
    assert "cyl.m_oil" in out and "more signals" not in out
    for units, expected in [("p=mm", "'mm' is not a unit of p"), ("cyl.pX=bar", "did you mean 'cyl.pB'"),
                            ("cyl.pA=mm", "cyl.pA is in Pa"), ("blorps", "unknown unit 'blorps'")]:
        code, _, err = cli("simulate", "flight-simulator", "--units", units, "--out", str(tmp_path / "x"))
        assert code == 2 and "--units" in err and expected in err and not (tmp_path / "x").exists(), err
    code, _, err = cli("simulate", "flight-simulator", "--units", "bar", "--si")
    assert code == 2 and "give one of them" in err


def test_cli_set_refuses_a_bare_number_the_model_gives_in_other_units(cli) -> None:
    # the file gives load.W in lbf: 3000 alone would be taken as 3000 N, a fifth of what was meant
    code, _, err = cli("simulate", "flight-simulator", "--set", "load.W=3000", "--write", "none")
    assert code == 2 and "in lbf ('6400 lbf')" in err and '--set "load.W=3000 lbf"' in err
    code, _, _ = cli("simulate", "flight-simulator", "--set", "cyl.k_stop=0", "--t-end", "0.1", "--write", "none")
    assert code == 0  # zero is zero in any unit
    code, _, _ = cli("simulate", "robot-arm", "--set", "load.m=30", "--t-end", "0.1", "--write", "none")
    assert code == 0  # robot-arm gives load.m in kg, SI: a bare number is unambiguous


def test_cli_simulate_accuracy_sets_the_tolerances(cli) -> None:
    code, out, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--json", "--accuracy", "0.1%")
    assert code == 0 and json.loads(out)["solver"]["rtol"] == pytest.approx(1e-5)
    code, _, err = cli("simulate", "flight-simulator", "--json", "--accuracy", "1e-3", "--rtol", "1e-5")
    assert code == 2 and "give one of them, not both" in err


def test_cli_export_then_simulate(tmp_path, cli) -> None:
    code, text, _ = cli("export", "flight-simulator")
    assert code == 0
    path = tmp_path / "fs.toml"
    path.write_text(text)
    code, out, _ = cli("simulate", str(path), "--t-end", "0.2", "--out", str(tmp_path))
    assert code == 0
    assert "simulated 'flight-simulator'" in out


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["simulate", "flight-simulator", "--set", "cyl.A_A=3 bar"], "wrong dimension"),
        (["simulate", "flight-simulator", "--set", "cyl.V_A0=-3 in^3"], "expected > 0"),
        (["simulate", "flight-simulator", "--set", "load.mass=3 kg"], "has no parameter 'mass'"),
        (["simulate", "flight-simulator", "--set", "nope.m=3 kg"], "no component 'nope'"),
        (["simulate", "flight-simulator", "--set", "load.m"], "expected COMPONENT.PARAMETER=VALUE"),
        (["simulate", "no-such-model"], "neither a built-in model"),
        (["simulate", "flight-simulator", "--t-end", "2 bar"], "--t-end"),
        (["validate", "nothing"], "no validation"),
    ],
)
def test_cli_bad_input_exit_2(argv, message, cli, tmp_path) -> None:
    code, _, err = cli(*([*argv, "--out", str(tmp_path)] if argv[0] == "simulate" else argv))
    assert code == 2
    assert message in err and "Traceback" not in err


def test_cli_models_and_validate(cli) -> None:
    code, out, _ = cli("models")
    assert code == 0
    assert "flight-simulator" in out
    code, out, _ = cli("validate", "flight-simulator", "--json")
    assert code == 0
    rows = json.loads(out)["flight-simulator"]
    assert {r["verdict"] for r in rows} >= {"reproduced", "NOT reproduced"}


IMPLAUSIBLE = ["--set", "source.amplitude=100 V", "--set", "cyl.k_stop=0", "--set", "cyl.c_stop=0", "--t-end", "2 s"]


def test_cli_warns_of_an_implausible_result_and_strict_refuses_it(tmp_path, cli) -> None:
    code, out, err = cli("simulate", "flight-simulator", *IMPLAUSIBLE, "--out", str(tmp_path / "a"), "--json")
    assert code == 0
    warnings = json.loads(out)["warnings"]
    # the piston runs through its missing stops; its chamber is no longer flagged since the servovalve's spool
    # stops at its travel (it opened to 28 times it, and the chamber's pressure left its bounds)
    assert {w["signal"] for w in warnings} == {"load.x"}
    assert all(w["message"] in err for w in warnings)  # and each is a warning line
    code, out, err = cli("simulate", "flight-simulator", *IMPLAUSIBLE, "--out", str(tmp_path / "b"), "--strict")
    assert code == 2 and "--strict" in err and "load.x" in err and "cyl.x_min" in err
    assert not (tmp_path / "b").exists()  # nothing written
    code, out, _ = cli("simulate", "flight-simulator", "--out", str(tmp_path / "c"), "--strict", "--json")
    assert code == 0 and json.loads(out)["warnings"] == []


@pytest.mark.parametrize(
    ("option", "value"),
    [("--rtol", "0"), ("--rtol", "nan"), ("--rtol", "1e10"), ("--rtol", "-1"), ("--points", "1"), ("--points", "2000000"),
     ("--accuracy", "2"), ("--accuracy", "abc"), ("--accuracy", "0%"), ("--accuracy", "nan")],
)
def test_cli_solver_options_are_refused_up_front(option, value, cli, tmp_path) -> None:
    code, _, err = cli("simulate", "flight-simulator", option, value, "--out", str(tmp_path))
    assert code == 2 and option in err and (value in err or f"{float(value):g}" in err) and "Traceback" not in err
    assert not any(tmp_path.iterdir())


def test_cli_components_and_describe(cli) -> None:
    code, out, _ = cli("components")
    assert code == 0 and "valves:" in out and "  Cylinder " in out and "hydroservo describe TYPE" in out
    code, out, _ = cli("describe", "Cylinder")
    assert code == 0 and "Double-acting cylinder" in out and "A_A          [m²]  0.002  > 0  piston area" in out
    code, out, _ = cli("describe", "Volume", "--json")
    assert code == 0 and json.loads(out)["parameters"][0]["name"] == "V"
    code, _, err = cli("describe", "Valve")
    assert code == 2 and "component type 'Valve': unknown" in err


def test_result_plot_without_arguments_shows_the_main_signals(tmp_path) -> None:
    import hydroservo as hs

    result = hs.load_model("flight-simulator").simulate(t_end=0.2, n_points=21)
    assert result.panels == [["vi", "eo"], ["xv"], ["ydot"], ["y"], ["p1", "p2"]]  # the model file's plots
    fig = result.plot(file=tmp_path / "r.png")
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert labels == ["vi, eo [V]", "xv [in]", "ydot [in/s]", "y [in]", "p1, p2 [psi]"]  # the model's units
    si = result.plot(units="si", file=tmp_path / "si.png")
    assert [ax.get_ylabel() for ax in si.axes] == ["vi, eo [V]", "xv [m]", "ydot [m/s]", "y [m]", "p1, p2 [Pa]"]
    legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert legend == ["vi: command voltage", "eo: error voltage at the RC network output"]


@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_servovalve_bench_writes_its_report_and_refuses_bad_values(tmp_path, cli) -> None:  # type: ignore[no-untyped-def]
    import json

    out = tmp_path / "sv"
    code, text, err = cli(
        "servovalve", "bench", "--points", "11", "--tests", "static,steps", "--out", str(out), "--json"
    )
    assert code == 0, err
    report = json.loads(text)
    rated = next(f for f in report["figures"] if f["figure"] == "rated flow at +rated current")
    assert rated["value"] == pytest.approx(11.99, abs=0.01) and rated["unit"] == "L/min"
    reaches = next(f for f in report["figures"] if f["figure"] == "step +-25 %: flapper reaches a nozzle")
    assert reaches["value"] == 1.0
    expected = ["characteristic.csv", "figures.csv", "flow-current.png", "steps.csv", "steps.png"]
    assert sorted(p.name for p in out.iterdir()) == expected
    code, _, err = cli("servovalve", "bench", "--tests", "static,noise", "--out", str(tmp_path / "bad"))
    assert code == 2 and "--tests 'static,noise'" in err
    code, _, err = cli("servovalve", "bench", "--set", "z_9=1", "--out", str(tmp_path / "bad"))
    assert code == 2 and "NAME a parameter of TwoStageServovalve" in err
    code, _, err = cli("servovalve", "bench", "--set", "x_0=0 m", "--out", str(tmp_path / "bad"))
    assert code == 2 and "sv.x_0 = '0 m' (= 0 m): expected > 0 m (flapper-nozzle gap at null)" in err
    code, _, err = cli("servovalve", "bench", "--set", "l_a=20 mm", "--out", str(tmp_path / "bad"))
    assert code == 2 and "the pivot must lie within the flapper" in err
    code, _, err = cli("servovalve", "bench", "--supply", "1 bar", "--out", str(tmp_path / "bad"))
    assert code == 2 and "--supply '1 bar': expected above the return" in err
    code, _, err = cli("servovalve", "bench", "--set", "K_f=-1 N/m", "--out", str(tmp_path / "bad"))
    assert code == 2 and "K_f" in err and not (tmp_path / "bad").exists()
    code, _, err = cli("servovalve", "bench", "--supply", "3 kg", "--out", str(tmp_path / "bad"))
    assert code == 2 and "--supply" in err
    code, _, err = cli("servovalve", "bench", "--current", "-1 mA", "--out", str(tmp_path / "bad"))
    assert code == 2 and "--current '-1 mA': expected a positive rated current" in err
    assert not (tmp_path / "bad").exists()


@pytest.mark.slow  # about 20 s: every parameter, three kinds of derivative
def test_servovalve_design_ranks_the_parameters(tmp_path, cli) -> None:  # type: ignore[no-untyped-def]
    import json

    code, text, err = cli("servovalve", "design", "--top", "3", "--out", str(tmp_path / "d"), "--json")
    assert code == 0, err
    report = json.loads(text)
    assert report["figures"]["rated_flow"]["value"] == pytest.approx(11.99, abs=0.01)
    assert report["figures"]["rated_flow"]["derivatives"] == "exact"
    assert report["elasticity"]["rated_flow"]["N"] == pytest.approx(1.0, abs=0.02)
    assert report["figures"]["f_90"]["value"] == pytest.approx(123.0, abs=2.0)
    assert sorted(p.name for p in (tmp_path / "d").iterdir()) == ["sensitivity.csv", "sensitivity.png"]
    code, _, err = cli("servovalve", "design", "--top", "0", "--out", str(tmp_path / "bad"))
    assert code == 2 and "--top 0" in err and not (tmp_path / "bad").exists()
    code, _, err = cli("servovalve", "design", "--figures", "bandwidth", "--out", str(tmp_path / "bad"))
    assert code == 2 and "--figures 'bandwidth'" in err and not (tmp_path / "bad").exists()


def test_servovalve_fit_catalogue_writes_loadable_models(tmp_path, cli) -> None:  # type: ignore[no-untyped-def]
    import json

    from hydroservo.io.component_file import read_component_file

    out = tmp_path / "cat"
    code, text, err = cli("servovalve", "fit-catalogue", "--orders", "2,3", "--out", str(out), "--json")
    assert code == 0, err
    report = json.loads(text)
    third = next(f for f in report["fits"] if f["order"] == "3")
    assert third["gain_error_dB"] < 0.5 and third["phase_error_deg"] < 3.0
    names = sorted(p.name for p in out.iterdir())
    assert names == ["catalogue-bode.png", "catalogue-order2.toml", "catalogue-order3.toml", "catalogue.csv"]
    table = read_component_file(out / "catalogue-order3.toml")
    assert table["type"] == "CatalogueServovalve" and table["order"] == "3"
    code, _, err = cli("servovalve", "fit-catalogue", "--orders", "4", "--out", str(tmp_path / "bad"))
    assert code == 2 and "--orders '4'" in err and not (tmp_path / "bad").exists()
    code, _, err = cli("servovalve", "fit-catalogue", "--amplitude", "150 %", "--out", str(tmp_path / "bad"))
    assert code == 2 and "--amplitude '150 %'" in err


def test_linearize_prints_modes_and_writes_its_files(tmp_path, cli) -> None:  # type: ignore[no-untyped-def]
    """The robot arm in steady motion: matrices and modes as JSON, the files written, the valve coefficients."""
    import json

    out = tmp_path / "lin"
    code, text, err = cli("linearize", "robot-arm", "--t", "0.3", "--free", "load.x", "--frequencies", "1,10,100",
                          "--out", str(out), "--json")
    assert code == 0, err
    report = json.loads(text)
    assert report["states"] == ["spool.s", "cyl.pA", "cyl.pB", "load.x", "load.v"]
    assert report["inputs"] == ["spool.u", "load.F_ext"]
    assert len(report["A"]) == 5 and len(report["B"][0]) == 2
    assert report["operating_point"]["drift"]["load.x"] > 0.05  # the arm moves at its steady speed
    (valve,) = report["valves"]
    assert valve["model"]["K_Qx_A"] == pytest.approx(valve["closed_form"]["K_Qx_A"], rel=1e-3)
    assert any(m["damping"] is not None and m["damping"] < 0.5 for m in report["modes"])  # the hydraulic resonance
    assert {f["input"] for f in report["frequency_response"]} == {"spool.u", "load.F_ext"}
    assert sorted(p.name for p in out.iterdir()) == ["robot-arm-bode.png", "robot-arm-linear.json", "robot-arm-poles.png"]
    code, text, _ = cli("linearize", "robot-arm", "--at", "initial", "--inputs", "supply.scale", "--outputs", "load.v",
                        "--out", str(tmp_path / "lin2"))
    assert code == 0 and "modes (slowest first)" in text


@pytest.mark.parametrize(
    "argv, patterns",
    [
        (["--free", "load.q"], [r"free", r"load\.q", r"not a state"]),
        (["--inputs", "valve.nothing"], [r"valve\.nothing", r"neither a component input nor a parameter"]),
        (["--outputs", "cyl.pC"], [r"cyl\.pC", r"not a state, output or alias"]),
        (["--at", "cyl.pQ=3bar"], [r"cyl\.pQ", r"not a state"]),
        (["--at", "cyl.pA=3 kg"], [r"cyl\.pA", r"kg"]),
        (["--at", "cyl.pA=3bar,junk"], [r"--at", r"junk", r"STATE=VALUE"]),
    ],
)
def test_linearize_refuses_bad_options(tmp_path, cli, argv, patterns) -> None:  # type: ignore[no-untyped-def]
    import re

    code, _, err = cli("linearize", "robot-arm", *argv, "--out", str(tmp_path / "out"))
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err
    for pat in patterns:
        assert re.search(pat, err), (pat, err)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_sensitivity_one_at_a_time_and_sobol(tmp_path, cli) -> None:  # type: ignore[no-untyped-def]
    """oat: a table and a family plot per factor; sobol: indices with intervals, the runs as Parquet, resumable."""
    import pandas as pd

    code, text, err = cli("sensitivity", "robot-arm", "--vary", "valve.c_v=1e-4..2e-4", "--levels", "3",
                          "--vary", "cyl.bulk_modulus=lee,constant", "--t-end", "0.8", "--points", "81",
                          "--out", str(tmp_path / "oat"))
    assert code == 0, err
    assert sorted(p.name for p in (tmp_path / "oat").iterdir()) == [
        "oat-cyl.bulk_modulus.png", "oat-valve.c_v.png", "oat.csv"]
    table = pd.read_csv(tmp_path / "oat" / "oat.csv")
    assert list(table["level"])[:3] == ["0.0001", "0.00015", "0.0002"] and len(table) == 5
    argv = ["sensitivity", "robot-arm", "--method", "sobol", "--n", "8", "--vary", "valve.c_v=1e-4..2e-4",
            "--vary", "load.m=15kg..35kg", "--t-end", "0.8", "--points", "81", "--out", str(tmp_path / "sobol"), "--json"]
    code, text, err = cli(*argv)
    assert code == 0, err
    report = json.loads(text)
    assert report["runs"]["runs"] == 8 * 4 and report["method"] == "sobol"
    row = next(r for r in report["indices"] if r["metric"] == "final(x_mm) [mm]" and r["parameter"] == "valve.c_v")
    assert row["ST"] > 0.5 and row["ST_conf"] >= 0
    runs = pd.read_parquet(tmp_path / "sobol" / "runs")
    assert len(runs) == 32 and set(runs["status"]) == {"ok"}
    (tmp_path / "sobol" / "indices.csv").unlink()
    (tmp_path / "sobol" / "indices.png").unlink()
    code, text, err = cli(*argv)  # the same study again: every run is read back, none run
    assert code == 0 and json.loads(text)["runs"]["resumed"] == 32


@pytest.mark.parametrize(
    "argv, patterns",
    [
        (["--vary", "valve.c_v"], [r"--vary", r"NAME=LOW\.\.HIGH"]),
        (["--vary", "valve.c_v=1e-4.."], [r"--vary", r"LOW\.\.HIGH"]),
        (["--method", "sobol", "--vary", "cyl.bulk_modulus=lee,constant"], [r"--method sobol", r"NAME=LOW\.\.HIGH"]),
        (["--method", "sobol", "--n", "100", "--vary", "load.m=1..2"], [r"n = 100", r"power of two"]),
        (["--vary", "load.m=1..2", "--metric", "final(q)"], [r"final\(q\)", r"not a state"]),
        (["--vary", "load.q=1..2"], [r"load", r"q"]),
        (["--vary", "cyl.bulk_modulus=lee,air"], [r"cyl\.bulk_modulus", r"'air'", r"lee"]),
        (["--vary", "load.m=2kg..1kg"], [r"load\.m", r"low < high"]),
        (["--vary", "load.m=1..2", "--vary", "load.m=3..4"], [r"load\.m", r"twice"]),
    ],
)
def test_sensitivity_refuses_bad_options(tmp_path, cli, argv, patterns) -> None:  # type: ignore[no-untyped-def]
    import re

    code, _, err = cli("sensitivity", "robot-arm", *argv, "--out", str(tmp_path / "out"))
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err, err
    for pat in patterns:
        assert re.search(pat, err), (pat, err)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").rglob("*.*"))


@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_ladder_prints_the_table_and_writes_its_files(tmp_path, cli) -> None:  # type: ignore[no-untyped-def]
    measured = tmp_path / "run_368.csv"
    measured.write_text("t [s],x [mm]\n0,0\n1.5,33.0\n")
    code, text, err = cli("ladder", "robot-arm", "--steps", "25.8,36.8", "--models", "nonlinear,linear,simplified-feedback",
                          "--measured", f"36.8={measured}", "--measured", f"25.8={measured}", "--points", "101",
                          "--out", str(tmp_path / "lad"), "--json")
    assert code == 0, err
    report = json.loads(text)
    assert report["reference"] == "measured" and report["parameter"] == "command.amplitude" and report["output"] == "x_mm"
    names = [m["model"] for m in report["models"]]
    assert names == ["nonlinear", "linear", "simplified-feedback", "improved nonlinear", "improved linear",
                     "improved simplified-feedback"]
    row = report["models"][3]
    assert row["error 36.8 % [%]"] == pytest.approx(100 * (row["displacement 36.8 % [mm]"] - 33.0) / 33.0)
    assert sorted(p.name for p in (tmp_path / "lad").iterdir()) == ["ladder-classes.png", "ladder-responses.png", "ladder.csv"]
    code, text, _ = cli("ladder", "robot-arm", "--steps", "36.8", "--models", "nonlinear,linear", "--out", str(tmp_path / "l2"))
    assert code == 0 and "improved linear" in text and "A accurate" in text


@pytest.mark.parametrize(
    "argv, patterns",
    [
        (["--steps", "0,50"], [r"--steps", r"0 to 100"]),
        (["--models", "linear,cubic"], [r"--models", r"'cubic'"]),
        (["--output", "x_cm"], [r"--output", r"x_cm"]),
        (["--parameter", "command.height"], [r"command", r"height"]),
        (["--measured", "36.8"], [r"--measured", r"STEP=FILE"]),
        (["--free", "load.q"], [r"load\.q", r"not a state"]),
    ],
)
def test_ladder_refuses_bad_options(tmp_path, cli, argv, patterns) -> None:  # type: ignore[no-untyped-def]
    import re

    code, _, err = cli("ladder", "robot-arm", *argv, "--out", str(tmp_path / "out"))
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err, err
    for pat in patterns:
        assert re.search(pat, err), (pat, err)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_linearize_simulates_sines_beside_the_linear_model(tmp_path, cli) -> None:  # type: ignore[no-untyped-def]
    code, text, err = cli("linearize", "robot-arm", "--t", "0.35", "--free", "load.x", "--inputs", "spool.u",
                          "--outputs", "load.v", "--frequencies", "1,10", "--simulate", "0.05", "--out",
                          str(tmp_path / "l"), "--json")
    assert code == 0, err
    sim = json.loads(text)["simulated_response"]
    assert sim["gain_dB"][0][0] is None or sim["gain_dB"][0][0] != sim["gain_dB"][0][0]  # 1 Hz: the stop first
    assert "stop" in sim["note"] and abs(sim["gain_dB"][0][1] - sim["linear_gain_dB"][1]) < 6
    assert (tmp_path / "l" / "robot-arm-bode-simulated.png").exists()


@pytest.mark.slow
def test_sensitivity_runs_on_a_dask_scheduler_by_its_address(tmp_path, cli) -> None:  # type: ignore[no-untyped-def]
    """--scheduler ADDRESS: the same command, its chunks on a two-worker cluster; the same indices as locally."""
    distributed = pytest.importorskip("distributed")
    argv = ["sensitivity", "robot-arm", "--method", "morris", "--n", "4", "--vary", "valve.c_v=1e-4..2e-4",
            "--vary", "load.m=15kg..35kg", "--t-end", "0.8", "--points", "81", "--chunk", "3", "--json"]
    code, text, err = cli(*argv, "--out", str(tmp_path / "local"))
    assert code == 0, err
    local = json.loads(text)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        code, text, err = cli(*argv, "--scheduler", cluster.scheduler_address, "--out", str(tmp_path / "dask"))
    assert code == 0, err
    remote = json.loads(text)
    assert remote["runs"]["where"] == "dask" and local["runs"]["where"] == "local"
    assert remote["indices"] == local["indices"]
    code, _, err = cli(*argv[:-1], "--scheduler", "tcp://127.0.0.1:9", "--out", str(tmp_path / "none"))
    assert code == 2 and "cannot connect" in err and not (tmp_path / "none").exists()


def test_report_shows_a_result_file_in_its_units_or_in_those_asked_for(tmp_path, cli) -> None:
    code, _, _ = cli("simulate", "flight-simulator", "--t-end", "0.2", "--write", "csv", "--out", str(tmp_path / "run"))
    csv = str(tmp_path / "run" / "flight-simulator.csv")
    code, out, _ = cli("report", csv, "--json", "--out", str(tmp_path / "a"))
    assert code == 0 and json.loads(out)["signals"]["p2"]["unit"] == "psi"  # as the file is written
    code, out, _ = cli("report", csv, "--units", "p=bar", "--json", "--out", str(tmp_path / "b"))
    p2 = json.loads(out)["signals"]["p2"]
    assert code == 0 and p2["unit"] == "bar" and 40 < p2["min"] < 60  # 772 psi = 53 bar at the start
    code, _, err = cli("report", csv, "--units", "cyl.pX=bar", "--out", str(tmp_path / "c"))
    assert code == 2 and "did you mean 'cyl.pB'" in err and not (tmp_path / "c").exists()
