"""Signal sources (hydroservo.components.signals): step, ramp, sine, square, table."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c


def test_sources() -> None:
    s = hs.System("sources", t_end=1.0)
    s.add(c.Step("step", amplitude=2.0, t_step=0.5))
    s.add(c.Ramp("ramp", slope=3.0, t_start=0.2, limit=1.5))
    s.add(c.Sine("sine", amplitude=1.0, frequency=2.0))
    s.add(c.Square("square", amplitude=1.0, frequency=2.0))
    s.add(c.Table("table", times=[0.0, 1.0], values=[0.0, 10.0]))
    s.add(c.Sum("sum", gain1=1.0, gain2=1.0))
    s.add(c.Lag("lag", tau=1.0))
    s.connect("step.y", "sum.u1")
    s.connect("ramp.y", "sum.u2")
    s.connect("sum.y", "lag.u")
    for name in ("sine", "square", "table"):
        s.add(c.Lag(f"l_{name}", tau=1.0))
        s.connect(f"{name}.y", f"l_{name}.u")
    r = s.simulate(t_eval=[0.0, 0.3, 0.4, 0.6, 0.9, 1.0])
    np.testing.assert_allclose(r["step.y"], [0, 0, 0, 2, 2, 2])
    np.testing.assert_allclose(r["ramp.y"], [0, 0.3, 0.6, 1.2, 1.5, 1.5])
    np.testing.assert_allclose(r["sine.y"], np.sin(4 * np.pi * r.t), atol=1e-12)
    np.testing.assert_allclose(r["square.y"], [1, -1, -1, 1, -1, 1])  # 2 Hz: + on the first half of each 0.5 s period
    np.testing.assert_allclose(r["table.y"], 10 * r.t)


def test_pulse_wave_staircase_and_decaying_step_at_known_times() -> None:
    """Hopsan's SignalPulseWave (D = 0.6 of a 1 s period from 1 s), SignalStaircase and
    SignalStepExponentialDelay (offset + A exp(-(t - t_step)/tau) from t_step) at times between their edges."""
    s = hs.System("sources", t_end=4.0)
    s.add(c.PulseWave("pw", amplitude=2.0, period=1.0, duty=0.6, t_start=1.0, offset=-1.0))
    s.add(c.Staircase("st", height=0.5, width=0.8, t_start=0.2))
    s.add(c.DecayingStep("ds", amplitude=3.0, tau=0.5, t_step=1.0, offset=1.0))
    t = np.array([0.5, 1.1, 1.55, 1.65, 2.05, 2.7, 3.3, 3.9])
    r = s.simulate(t_eval=t)
    np.testing.assert_allclose(r["pw.y"], [-1, 1, 1, -1, 1, -1, 1, -1])
    np.testing.assert_allclose(r["st.y"], 0.5 * np.floor(np.clip(t - 0.2, 0, None) / 0.8))
    np.testing.assert_allclose(r["ds.y"], np.where(t >= 1.0, 1.0 + 3.0 * np.exp(-(t - 1.0) / 0.5), 1.0), atol=1e-12)


def test_an_integrator_does_not_step_blindly_across_a_staircases_edges() -> None:
    """The staircase's edges are events of the compiled solvers: each of the 9 edges ends a step, and the integral
    of a staircase of 1 every 0.1 s, 0.1 * (0 + 1 + ... + 9) = 4.5 at 1 s, is within the run's relative
    tolerance (1e-5 at accuracy 1e-3) times the 9 edges."""
    s = hs.System("stairs", t_end=1.0)
    s.add(c.Staircase("st", height=1.0, width=0.1))
    s.add(c.Integrator("i"))
    s.connect("st.y", "i.u")
    r = s.simulate(accuracy=1e-3, method="rodas3")
    assert r.stats["nevents"] == 9
    assert r["i.y"][-1] == pytest.approx(4.5, rel=9e-5)


def test_table_indexed_by_its_input_interpolates_and_holds_outside() -> None:
    """``index = "input"``: a lookup table of its input (Hopsan's Signal1DLookupTable), linear between the
    breakpoints and held at the end values outside them, on a ramp from -1 to 5."""
    s = hs.System("lookup", t_end=6.0)
    s.add(c.Ramp("u", offset=-1.0, slope=1.0, t_start=0.0))
    s.add(c.Table("f", times=[0.0, 1.0, 3.0], values=[1.0, 3.0, 0.0], index="input", scale=2.0))
    s.connect("u.y", "f.u")
    r = s.simulate(t_eval=[0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0])
    u = r["u.y"]
    closed = np.where(u < 0, 1.0, np.where(u < 1, 1 + 2 * u, np.where(u < 3, 3 - 1.5 * (u - 1), 0.0)))
    np.testing.assert_allclose(r["f.y"], 2.0 * closed, atol=1e-12)
    with pytest.raises(hs.errors.ParameterError, match="strictly increasing breakpoints of the input u"):
        c.Table("f", times=[0.0, 2.0, 1.0], values=[0.0, 1.0, 2.0], index="input")
    assert c.Table("g", times=[0.0, 1.0], values=[0.0, 1.0]).INPUTS == {}  # a time table reads no input


def test_lookup_table_and_pid_options_are_written_to_and_read_from_model_files(tmp_path) -> None:
    """A lookup table (index = input, its breakpoints and values inline) and a PID with its new options survive a
    model file: written by model_to_toml, read back, the same outputs."""
    from hydroservo.io import model_to_toml, read_model

    s = hs.System("written", t_end=2.0)
    s.add(c.Ramp("u", offset=-0.5, slope=1.0))
    s.add(c.Table("f", times=[0.0, 1.0], values=[2.0, 4.0], index="input"))
    s.add(c.Constant("d", value=0.25))
    s.add(c.PID("p", Kp=1.0, Ki=2.0, Kd=1.0, derivative="input", anti_windup="tracking", T_t=0.2, track_upper=3.0))
    s.connect("u.y", "f.u")
    s.connect("f.y", "p.e")
    s.connect("d.y", "p.de")
    path = tmp_path / "written.toml"
    path.write_text(model_to_toml(s), encoding="utf-8")
    again = read_model(path)
    assert again["f"].option("index") == "input" and again["p"].option("anti_windup") == "tracking"
    t = [0.0, 0.5, 1.0, 1.5, 2.0]
    a, b = s.simulate(t_eval=t), again.simulate(t_eval=t)
    np.testing.assert_allclose(b["f.y"], a["f.y"])
    np.testing.assert_allclose(b["p.y"], a["p.y"])
    np.testing.assert_allclose(a["f.y"], np.interp(np.array(t) - 0.5, [0.0, 1.0], [2.0, 4.0]))


def test_table2d_is_bilinear_between_its_breakpoints_and_held_outside() -> None:
    """Table2D (Hopsan's Signal2DLookupTable): within its breakpoints the bilinear interpolation
    y = sum_ij V_ij a_i(r) b_j(c) of the hats a_i, b_j, each input held at its first and last breakpoint outside;
    a table of unequal breakpoints (rows 0, 1, 3; cols -1, 2) against that closed form along a diagonal."""
    V = np.array([[0.0, 3.0], [1.0, -2.0], [5.0, 4.0]])
    s = hs.System("t2", t_end=6.0)
    s.add(c.Ramp("r", offset=-1.0, slope=1.0))
    s.add(c.Ramp("q", offset=-2.0, slope=1.0))
    s.add(c.Table2D("T", rows=[0.0, 1.0, 3.0], cols=[-1.0, 2.0], values=V, scale=2.0))
    s.connect("r.y", "T.row")
    s.connect("q.y", "T.col")
    t = np.linspace(0.0, 6.0, 25)
    r = s.simulate(t_eval=t)
    row, col = np.clip(t - 1.0, 0.0, 3.0), np.clip(t - 2.0, -1.0, 2.0)
    a = [np.interp(row, [0.0, 1.0, 3.0], e) for e in np.eye(3)]
    b = [np.interp(col, [-1.0, 2.0], e) for e in np.eye(2)]
    expected = sum(V[i, j] * a[i] * b[j] for i in range(3) for j in range(2))
    np.testing.assert_allclose(r["T.y"], 2.0 * expected, atol=1e-12)
    from hydroservo.errors import ParameterError

    with pytest.raises(ParameterError, match="T.rows: expected strictly increasing breakpoints"):
        c.Table2D("T", rows=[0.0, 0.0, 1.0], cols=[0.0, 1.0], values=np.zeros((3, 2)))
    with pytest.raises(ParameterError, match="values of 2 by 2"):
        c.Table2D("T", rows=[0.0, 1.0], cols=[0.0, 1.0], values=np.zeros((3, 2)))


def test_table3d_reproduces_a_multilinear_function_and_holds_its_inputs_outside() -> None:
    """Table3D (Hopsan's Signal3DLookupTable): trilinear interpolation reproduces a multilinear function
    f = 1 + 2r - 3c + 0.5q + rcq exactly between its breakpoints (unequally spaced: rows 0, 1, 3; cols -1, 2;
    planes 0, 0.5, 2), and each input is held at its first or last breakpoint outside them."""
    rows, cols, planes = np.array([0.0, 1.0, 3.0]), np.array([-1.0, 2.0]), np.array([0.0, 0.5, 2.0])

    def f(r: np.ndarray, q_c: np.ndarray, q: np.ndarray) -> np.ndarray:
        return 1.0 + 2.0 * r - 3.0 * q_c + 0.5 * q + r * q_c * q

    V = f(*np.meshgrid(rows, cols, planes, indexing="ij"))
    s = hs.System("t3", t_end=6.0)
    s.add(c.Ramp("r", offset=-1.0, slope=1.0))
    s.add(c.Ramp("q", offset=-2.0, slope=1.0))
    s.add(c.Ramp("p", offset=-0.5, slope=0.5))
    s.add(c.Table3D("T", rows=rows, cols=cols, planes=planes, values=V))
    s.connect("r.y", "T.row")
    s.connect("q.y", "T.col")
    s.connect("p.y", "T.plane")
    t = np.linspace(0.0, 6.0, 25)
    r = s.simulate(t_eval=t)
    expected = f(np.clip(t - 1.0, 0.0, 3.0), np.clip(t - 2.0, -1.0, 2.0), np.clip(0.5 * t - 0.5, 0.0, 2.0))
    np.testing.assert_allclose(r["T.y"], expected, atol=1e-12)
    from hydroservo.errors import ParameterError

    with pytest.raises(ParameterError, match="T.planes: expected strictly increasing breakpoints"):
        c.Table3D("T", rows=rows, cols=cols, planes=[0.0, 0.0, 1.0], values=V)
    with pytest.raises(ParameterError, match="values of 3 by 2 by 2"):
        c.Table3D("T", rows=rows, cols=cols, planes=[0.0, 1.0], values=V)
