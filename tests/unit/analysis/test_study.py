"""Step metrics against closed forms; designs; the study table and plots of a batch."""

from __future__ import annotations

import math

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.analysis import grid, sample, step_metrics
from hydroservo.errors import ParameterError


def test_step_metrics_of_a_first_order_lag() -> None:
    # y = 1 - exp(-t/tau): 10-90 % rise tau ln 9, 2 % settling tau ln 50, no overshoot
    t = np.linspace(0.0, 10.0, 100_001)
    m = step_metrics(t + 1.0, 3.0 * (1 - np.exp(-t / 0.5)), t_step=1.0, y_final=3.0, reference=3.2)
    assert m["rise_time"] == pytest.approx(0.5 * math.log(9), rel=1e-6)
    assert m["settling_time"] == pytest.approx(0.5 * math.log(50), rel=1e-6)
    assert m["overshoot"] == 0.0 and m["steady_state_error"] == pytest.approx(0.2)


def test_step_metrics_of_a_second_order_system() -> None:
    # underdamped unit step: overshoot exp(-zeta pi / sqrt(1 - zeta^2)), peak at pi / omega_d
    zeta, wn = 0.3, 10.0
    wd = wn * math.sqrt(1 - zeta**2)
    t = np.linspace(0.0, 10.0, 200_001)
    y = 1 - np.exp(-zeta * wn * t) * (np.cos(wd * t) + zeta / math.sqrt(1 - zeta**2) * np.sin(wd * t))
    m = step_metrics(t, y, y_final=1.0)
    assert m["overshoot"] == pytest.approx(100 * math.exp(-zeta * math.pi / math.sqrt(1 - zeta**2)), rel=1e-6)
    assert m["peak_time"] == pytest.approx(math.pi / wd, rel=1e-4)
    # the 2 % band is left for the last time where the envelope-bounded response crosses it: below 4/(zeta wn)
    assert 0.8 * 4 / (zeta * wn) < m["settling_time"] < 4 / (zeta * wn)


def test_step_metrics_of_a_flat_or_unsettled_response() -> None:
    t = np.linspace(0, 1, 11)
    flat = step_metrics(t, np.ones(11))
    assert math.isnan(flat["rise_time"]) and math.isnan(flat["overshoot"]) and flat["final"] == 1.0
    ramp = step_metrics(t, t, y_final=2.0)
    assert math.isnan(ramp["settling_time"])  # still outside the band at the end


def test_grid_and_sample() -> None:
    g = grid({"a.x": [1, 2], "a.y": ["1 mm", "2 mm", "3 mm"]})
    assert g["a.x"] == [1, 1, 1, 2, 2, 2] and g["a.y"][:3] == ["1 mm", "2 mm", "3 mm"]
    with pytest.raises(ParameterError, match="a.x = '12'"):
        grid({"a.x": "12"})
    s = sample({"a.x": ("2 mm", "5 mm"), "a.y": (1e3, 1e6)}, 256, log=["a.y"], seed=3)
    x = np.array([float(v.split()[0]) for v in s["a.x"]])
    assert all(v.endswith(" mm") for v in s["a.x"]) and 2 <= x.min() and x.max() <= 5
    y = np.log10(s["a.y"])
    # a Sobol sequence of 256 points puts 64 in each quarter of the (log) range
    assert np.histogram(y, bins=4, range=(3, 6))[0].tolist() == [64, 64, 64, 64]
    assert sample({"a.x": (0, 1)}, 5, method="random", seed=1) == sample({"a.x": (0, 1)}, 5, method="random", seed=1)
    for bad, pattern in [
        ({"a.x": (1, 1)}, "low < high"),
        ({"a.x": ("1 mm", "2 m")}, "one unit"),
        ({"a.x": (-1, 1)}, None),
    ]:
        if pattern:
            with pytest.raises(ParameterError, match=pattern):
                sample(bad, 4)
    with pytest.raises(ParameterError, match="positive bounds"):
        sample({"a.x": (-1, 1)}, 4, log=["a.x"])


def _servo() -> hs.System:
    """A first-order position loop: x' = K (r - x); closed form 1 - exp(-K t)."""
    s = hs.System("loop", t_end=1.0)
    s.add(c.Step("r", unit="m", amplitude=0.1))
    s.add(c.Sum("e", unit="m"))
    s.add(c.Lag("x", unit="m", K=1.0, tau=0.1))
    s.connect("r.y", "e.u1")
    s.connect("x.y", "e.u2")
    s.connect("e.y", "x.u")
    return s


def test_batch_table_has_parameters_status_and_metrics(tmp_path) -> None:
    s = _servo()
    b = s.batch({"x.tau": [0.1, 0.2, -1.0]}, n_points=2001)
    assert repr(b).startswith("<BatchResult of 'loop': 3 runs, 2 ok (0 implausible), 1 failed; varied x.tau;")
    df = b.table("x.y", unit="mm", y_final=50.0, reference=100.0)
    assert df["x.tau [s]"].tolist()[:2] == [0.1, 0.2] and df["status"].tolist() == ["ok", "ok", "failed"]
    # closed loop y' = (r - 2y)/tau: time constant tau/2, final r/2 = 50 mm; rise (tau/2) ln 9
    assert df["x.y rise_time [s]"][0] == pytest.approx(0.05 * math.log(9), rel=1e-3)
    assert df["x.y rise_time [s]"][1] == pytest.approx(0.1 * math.log(9), rel=1e-3)
    assert df["x.y steady_state_error [mm]"][0] == pytest.approx(50.0)
    assert math.isnan(df["x.y rise_time [s]"][2])
    fig = b.plot("x.y", unit="mm", file=tmp_path / "family.png")
    assert (tmp_path / "family.png").stat().st_size > 0 and "1 failed run(s) not drawn" in fig.axes[0].get_title()
    from hydroservo.plotting.study import plot_metrics

    plot_metrics(df, "x.tau", ["x.y rise_time", "x.y settling_time"], file=tmp_path / "metrics.png")
    assert (tmp_path / "metrics.png").stat().st_size > 0
