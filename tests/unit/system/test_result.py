"""Simulation results (hydroservo.system.result): CSV, MAT, plot, units, summary."""

from __future__ import annotations

import numpy as np
import pytest


def test_result_exports(tmp_path, spring_mass) -> None:
    r = spring_mass().simulate(t_end=0.1, n_points=11)
    csv = r.to_csv(tmp_path / "r.csv")
    header = csv.read_text(encoding="utf-8-sig").splitlines()[0]
    assert header.startswith("t [s],load.x [m],load.v [m/s]")  # no units given: SI
    import scipy.io

    r.to_mat(tmp_path / "r.mat")
    mat = scipy.io.loadmat(tmp_path / "r.mat")
    np.testing.assert_allclose(mat["load_x"].ravel(), r["load.x"])
    r.plot("load.x", ["load.v"], units={"load.x": "mm"}, file=tmp_path / "r.png")
    assert (tmp_path / "r.png").stat().st_size > 1000
    assert r.get("load.x", "mm")[0] == pytest.approx(10.0)
    s = r.summary()["load.x"]
    assert s["unit"] == "m" and s["max"] == pytest.approx(0.01)


def test_signals_are_read_when_asked_and_equal_the_whole_set() -> None:
    import hydroservo as hs

    system = hs.load_model("flight-simulator")
    model = system.build()
    lazy = system.simulate(t_end=0.2, n_points=101)
    assert set(lazy._pending) == {*model.state_names, *model.output_names}  # nothing read yet
    y, p2 = lazy["y"], lazy["p2"]
    assert "y" not in lazy._pending and "cyl.pA" in lazy._pending  # only what was read
    whole = system.simulate(t_end=0.2, n_points=101).data
    assert list(lazy.data) == [*model.state_names, *model.output_names] == list(whole)
    for name, values in whole.items():
        np.testing.assert_array_equal(lazy[name], values)
    np.testing.assert_array_equal(y, whole["y"])
    np.testing.assert_array_equal(p2, whole["p2"])


def test_a_compiled_model_is_shared_by_structure_only() -> None:
    # Loading a model again finds it built; what changes the equations (a valve's compensation tables held in a
    # dict, a signal block's unit) is structure, and gets a model of its own.
    import hydroservo as hs
    from hydroservo.analysis.ladder import _tables_off

    arm = hs.load_model("robot-arm")
    assert hs.load_model("robot-arm").build() is arm.build()
    plain = arm.copy()
    _tables_off(plain)
    assert plain.build() is not arm.build()
    moved = arm.copy()
    moved.set("load.m", "40 kg")  # a parameter: the same equations
    assert moved.build() is arm.build()
    a = hs.System("a")
    a.add(hs.components.Step("s", unit="mm", amplitude=1.0))
    b = hs.System("a")
    b.add(hs.components.Step("s", unit="bar", amplitude=1.0))
    assert a.build() is not b.build() and a.build().units["s.y"] != b.build().units["s.y"]


def test_offset_units_hold_in_plots_tables_and_files(tmp_path) -> None:
    # an absolute pressure is the gauge one plus the atmosphere: every way a result is shown adds it
    import warnings

    import hydroservo as hs
    from hydroservo.io.notebook import signal_table
    from hydroservo.io.results import read_csv

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = hs.load_model("robot-arm").simulate(t_end=0.1, n_points=11)
    assert r.get("tank.p", "bar_abs")[0] == pytest.approx(1.01325)
    assert r.summary("p=bar_abs")["tank.p"]["final"] == pytest.approx(1.01325)
    fig = r.plot(["tank.p"], units="p=bar_abs", file=tmp_path / "p.png")
    assert fig.axes[0].lines[0].get_ydata()[0] == pytest.approx(1.01325)
    row = next(row for row in signal_table(r, r.shown_units("p=bar_abs")).rows if row[0] == "cyl.pA")
    assert row[2] == pytest.approx(r.get("cyl.pA", "bar")[-1] + 1.01325)
    # ASCII files read back, whatever unit was chosen (um, not µm turned into ?m)
    path = r.to_csv(tmp_path / "r.csv", units="um, p=bar_abs", ascii=True)
    assert path.read_bytes().isascii() and b"load.x [um]" in path.read_bytes()
    back = read_csv(path)
    assert back["load.x"] == pytest.approx(r["load.x"], rel=1e-9) and back["cyl.pA"] == pytest.approx(r["cyl.pA"], rel=1e-8)


def test_one_axis_one_unit() -> None:
    import hydroservo as hs

    r = hs.load_model("robot-arm").simulate(t_end=0.05, n_points=6)
    import matplotlib.pyplot as plt

    with pytest.warns(UserWarning, match="not shown"):
        fig = r.plot(["cyl.pA", "cyl.pB"], units="cyl.pA=psi")
    plt.close(fig)
    assert fig.axes[0].get_ylabel() == "cyl.pA, cyl.pB [psi]"
    ratio = fig.axes[0].lines[1].get_ydata()[-1] / r["cyl.pB"][-1]
    assert ratio == pytest.approx(1 / 6894.757, rel=1e-6)  # pB drawn in psi too, not in the model's bar
    with pytest.raises(hs.ParameterError, match="cyl.pA is in Pa"):
        r.summary("cyl.pA=mm")


def test_a_result_file_keeps_temperatures_in_degc(tmp_path) -> None:
    from hydroservo.io.results import read_csv

    path = tmp_path / "T.csv"
    path.write_text("t [s],oil.T [°C],oil.p [bar]\n0,40,1\n1,41,2\n", encoding="utf-8")
    back = read_csv(path)
    assert back.units["oil.T"] == "degC" and back["oil.T"][0] == pytest.approx(40.0)
    assert back["oil.p"][1] == pytest.approx(2e5)


def test_a_panel_of_many_long_names_is_labelled_by_what_they_are() -> None:
    """The names of a panel label its axis while they fit beside it (the legend names them too); past that the
    axis says what they have in common: their description, else their quantity, else how many they are."""
    from hydroservo.plotting import axis_label as _axis_label

    assert _axis_label(["p1", "p2"], {}, "Pa") == "p1, p2 [Pa]"
    many = [f"Hydraulic_Volume_{k}.p" for k in range(6)]
    assert _axis_label(many, dict.fromkeys(many, "pressure in a volume"), "Pa") == "pressure in a volume [Pa]"
    assert _axis_label(many, {many[0]: "pressure"}, "Pa") == "pressure [Pa]"
    assert _axis_label(many, {}, "-") == "6 signals [-]"
    assert _axis_label(["c_4_3_Servo_Valve_with_Load_Sensing_Port_1_spool.xv"], {}, "m") == "position [m]"
