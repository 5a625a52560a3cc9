"""Simulation results (hydroservo.system.result): CSV, MAT, plot, units, summary."""

from __future__ import annotations

import numpy as np
import pytest


def test_result_exports(tmp_path, spring_mass) -> None:
    r = spring_mass().simulate(t_end=0.1, n_points=11)
    csv = r.to_csv(tmp_path / "r.csv")
    header = csv.read_text().splitlines()[0]
    assert header.startswith("t [s],load.x [m],load.v [m/s]")
    import scipy.io

    r.to_mat(tmp_path / "r.mat")
    mat = scipy.io.loadmat(tmp_path / "r.mat")
    np.testing.assert_allclose(mat["load_x"].ravel(), r["load.x"])
    r.plot("load.x", ["load.v"], units={"load.x": "mm"}, file=tmp_path / "r.png")
    assert (tmp_path / "r.png").stat().st_size > 1000
    assert r.get("load.x", "mm")[0] == pytest.approx(10.0)
    s = r.summary()["load.x"]
    assert s["unit"] == "m" and s["max"] == pytest.approx(0.01)
