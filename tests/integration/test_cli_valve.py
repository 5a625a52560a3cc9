"""``hydroservo valve fit``, ``valve bode`` and ``valve fit-dynamics`` on the servo-solenoid valve of FerreiraND."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from hydroservo.data import parameter_set
from hydroservo.identification import spool_response
from hydroservo.io import read_component_file
from hydroservo.laws import pseudo_section as ps
from hydroservo.units import is_bare_number, to_si
from hydroservo.validation import printed_digit
from hydroservo.validation.ferreira import published_dynamics

PAPER = parameter_set("FerreiraND")
#: The KBSDG4V-3 datasheet of FerreiraND section 5, as printed (the parameter set's [datasheet] table).
DATASHEET = {k: v for k, v in PAPER.table("datasheet").items() if k != "name"}


def datasheet_toml(**changes: str) -> str:
    """A user's datasheet file with the published values (bare numbers as TOML numbers), ``changes`` replacing some."""
    values = DATASHEET | changes
    lines = (f"{k} = {v}" if is_bare_number(v) else f'{k} = "{v}"' for k, v in values.items())
    return '[datasheet]\nname = "test valve"\n' + "\n".join(lines) + "\n"


def test_valve_fit_cli_json_and_parameter_file(
    tmp_path: Path, cli, ferreira_printed: dict[str, dict[str, str]]
) -> None:
    ds = tmp_path / "valve.toml"
    ds.write_text(datasheet_toml())
    code, out, _ = cli("valve", "fit", str(ds), "--out", str(tmp_path / "fit"), "--json")
    assert code == 0
    data = json.loads(out)
    # k and gamma as FerreiraND section 5 prints them (parameter set FerreiraND, [variable]): gamma to one unit in
    # its last printed digit; k is K_p0 itself (in the exponential core P_L = tanh(k x_s)), so pytest's default 1e-6
    k, gamma = ferreira_printed["variable"]["k"], ferreira_printed["variable"]["gamma"]
    assert data["parameters"]["k"] == pytest.approx(float(k))
    assert data["parameters"]["gamma"] == pytest.approx(float(gamma.split()[0]), abs=printed_digit(gamma))
    lpm = to_si("1 L/min", "m^3/s")
    K_q0_eq23 = PAPER.si("datasheet", "q_lk0", "m^3/s") / lpm * PAPER.si("datasheet", "K_p0", "") / 2
    K_q0 = PAPER.si("datasheet", "K_q0", "m^3/s") / lpm
    # eq. 23 (K_q0 = q_lk0 K_p0 / 2) holds for any sections of a matched symmetrical valve, so the unmatched K_q0
    # is 24.82 L/min, not the datasheet's 28. The CLI's K_q0 is a finite-difference slope: 1e-6 as in
    # unit/laws/test_pseudo_section.py::test_eq23_holds_for_any_pseudo_sections (was abs 0.01 on a typed 24.82).
    assert data["characteristics"]["K_q0"] == pytest.approx(K_q0_eq23, rel=1e-6)
    assert data["deviation"]["K_q0"] == pytest.approx(K_q0_eq23 / K_q0 - 1, abs=1e-6)
    for f in data["files"].values():
        assert Path(f).stat().st_size > 0
    comp = read_component_file(data["files"]["parameters"])
    assert comp["type"] == "PseudoSectionValve" and comp["structure"] == "variable"

    code, out, _ = cli(
        "valve",
        "fit",
        "KBSDG4V-3",
        "--structure",
        "fixed",
        "--match",
        "pressure-gain,flow-gain",
        "--out",
        str(tmp_path / "fix"),
        "--json",
    )
    assert code == 0
    k1 = ferreira_printed["fixed"]["k1"]  # FerreiraND section 5, [fixed]: to one unit in its last printed digit
    assert json.loads(out)["parameters"]["k1"] == pytest.approx(float(k1.split()[0]), abs=printed_digit(k1))


def test_bode_and_fit_dynamics_cli(tmp_path: Path, cli) -> None:
    code, out, _ = cli(
        "valve",
        "bode",
        "KBSDG4V-3",
        "--amplitudes",
        "5,50",
        "--frequencies",
        "20:200:20",
        "--out",
        str(tmp_path / "bode"),
        "--json",
    )
    assert code == 0
    data = json.loads(out)
    assert np.shape(data["gain_dB"]) == (2, 10)
    # The -3 dB frequency at 5 % against the same published model (FerreiraND section 6, the [dynamics] table of the
    # parameter set FerreiraND) computed independently of the CLI: its gain on a 1 Hz grid over the 20 Hz interval
    # in which the CLI's 20:200:20 grid crosses -3 dB, interpolated there. Tolerance: the crossing is interpolated
    # linearly in u = ln f (FrequencyResponse.crossing, as a Bode plot draws it); over a step du, a gain g(u) makes
    # that err by at most du^2/8 max|g_uu| / min|g_u| in u, that is f times as much in frequency; the CLI's step
    # plus the reference's 1 Hz step, with g_u and g_uu taken from the fine curve.
    # The paper's own figure, "typically 200 Hz" for +-5 % (section 1), is an information row of the validation.
    f_cli = data["bandwidth"]["5 %"]["f_-3dB_Hz"]
    coarse_f, coarse_g = np.array(data["frequencies_Hz"]), np.array(data["gain_dB"][0])
    i = np.flatnonzero(coarse_g < -3.0)[0]
    fine_f = np.arange(coarse_f[i - 1], coarse_f[i] + 0.5, 1.0)
    fine_g = spool_response(published_dynamics(), [0.05], fine_f).gain_db[0]
    assert np.all(np.diff(fine_g) < 0)  # the gain falls through the interval: one crossing
    f_ref = float(np.interp(-3.0, fine_g[::-1], fine_f[::-1]))
    u = np.log(fine_f)
    slope = np.gradient(fine_g, u)
    curvature = np.gradient(slope, u)
    du = np.log(coarse_f[i] / coarse_f[i - 1])
    du_ref = np.log(fine_f[1] / fine_f[0])
    tolerance = f_ref * (du**2 + du_ref**2) / 8 * np.max(np.abs(curvature)) / np.min(np.abs(slope))
    assert f_cli == pytest.approx(f_ref, abs=tolerance)
    csv = data["files"]["csv"]
    code, out, _ = cli("valve", "fit-dynamics", csv, "--model", "second-order", "--out", str(tmp_path / "f"), "--json")
    assert code == 0
    fit = json.loads(out)["fits"]["second-order"]
    assert fit["parameters"]["omega_n"] > 0 and fit["parameters"]["delay"] >= 0
    comp = read_component_file(json.loads(out)["files"]["parameters_second-order"])
    assert comp["type"] == "SpoolSecondOrder"


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["valve", "fit", "KBSDG4V-3", "--match", "pressure-gain"], "exactly two"),
        (["valve", "fit", "nonexistent.toml"], "cannot read"),
        (["valve", "fit", "KBSDG4V-3", "--match", "pressure-gain,speed"], "not a null characteristic"),
        (["valve", "bode", "KBSDG4V-3", "--amplitudes", "5,x"], "comma-separated numbers"),
        (["valve", "bode", "KBSDG4V-3", "--amplitudes", "150"], "0 < amplitude <= 100 % of stroke"),
        (["valve", "fit-dynamics", "missing.csv"], "cannot read|No such file"),
    ],
)
def test_valve_cli_bad_input_exits_2(argv: list[str], message: str, cli, tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, _, err = cli(*argv)
    assert code == 2
    assert err.startswith("hydroservo: error:")
    assert re.search(message, err), err


def test_datasheet_with_negative_flow_exits_2(tmp_path: Path, cli) -> None:
    ds = tmp_path / "bad.toml"
    ds.write_text(datasheet_toml(q_lk0=f"-{DATASHEET['q_lk0']}"))
    code, _, err = cli("valve", "fit", str(ds), "--out", str(tmp_path))
    assert code == 2 and "q_lk0" in err and "positive" in err


def test_valve_fit_to_measured_curves_cli(tmp_path: Path, cli) -> None:
    from hydroservo.identification import fit_datasheet

    true = fit_datasheet(PAPER.table("datasheet"))
    P_s = PAPER.si("datasheet", "P_s", "Pa")  # the bench of the built-in KBSDG4V-3
    x = np.linspace(-0.06, 0.06, 25)
    A_p, A_n = true.sections(x)
    rows = ["x_s [-],P_L [-],q_lk [L/min],Q_L [L/min]"]
    for xi, pl, q, ql in zip(
        x,
        ps.relative_load_pressure(A_p, A_n),
        ps.leakage_blocked(A_p, A_n, P_s) * 6e4,
        ps.load_flow_no_load(A_p, A_n, P_s) * 6e4,
    ):
        rows.append(f"{xi:.12g},{pl:.12g},{q:.12g},{ql:.12g}")
    csv = tmp_path / "curves.csv"
    csv.write_text("\n".join(rows) + "\n")
    code, out, _ = cli("valve", "fit", "KBSDG4V-3", "--curves", str(csv), "--out", str(tmp_path), "--json")
    assert code == 0
    data = json.loads(out)
    assert data["match"] == ["curves"]
    assert data["parameters"]["k"] == pytest.approx(true.params["k"], rel=1e-5)  # exact curves of `true`
    assert data["deviation"]["rms_q_lk"] < 1e-6
    csv.write_text("x_s [-],P_L [-],q_lk\n0,0,1\n")
    code, _, err = cli("valve", "fit", "KBSDG4V-3", "--curves", str(csv), "--out", str(tmp_path))
    assert code == 2 and "expected a unit in brackets" in err
