"""The engine (hydroservo.system): simulation against analytic solutions, parameters, trim, batch, errors, C code."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import SolverError, TrimError
from hydroservo.system.native import has_compiler

needs_compiler = pytest.mark.skipif(not has_compiler(), reason="no C compiler")


def test_undamped_spring_mass_matches_cosine(spring_mass) -> None:
    r = spring_mass().simulate(t_end=1.0, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(r["load.x"], 0.01 * np.cos(20.0 * r.t), atol=1e-9)


def test_damped_spring_mass_matches_analytic_solution(spring_mass) -> None:
    # m x'' + B x' + k x = 0, x(0) = x0, x'(0) = 0
    m, B, k, x0 = 2.0, 16.0, 800.0, 0.01
    r = spring_mass(B=B).simulate(t_end=1.0, rtol=1e-10, atol=1e-12)
    wn, zeta = np.sqrt(k / m), B / (2 * np.sqrt(k * m))
    wd = wn * np.sqrt(1 - zeta**2)
    exact = x0 * np.exp(-zeta * wn * r.t) * (np.cos(wd * r.t) + zeta * wn / wd * np.sin(wd * r.t))
    np.testing.assert_allclose(r["load.x"], exact, atol=1e-9)


def test_parameters_change_without_rebuild(spring_mass) -> None:
    s = spring_mass()
    model = s.build()
    r = s.simulate(t_end=0.1, params={"load.k_spring": "3.2 kN/m"})
    assert s.build() is model
    np.testing.assert_allclose(r["load.x"], 0.01 * np.cos(40.0 * r.t), atol=1e-6)


def test_trim_finds_equilibrium_of_loaded_spring() -> None:
    s = hs.System("hanging")
    s.add(c.Mass("load", m=10.0, W=98.0665, k_spring=1000.0, B=50.0))
    x = s.trim()
    assert x["load.x"] == pytest.approx(-98.0665 / 1000.0, rel=1e-9)
    assert x["load.v"] == pytest.approx(0.0, abs=1e-12)
    r = s.simulate(t_end=0.2, initial="trim")
    np.testing.assert_allclose(r["load.x"], x["load.x"], rtol=1e-9)


def test_trim_reports_failure() -> None:
    s = hs.System("pushed")
    s.add(c.Mass("load", m=1.0, incline=0.0))
    s.add(c.Step("f", unit="N", amplitude=1.0))
    s.connect("f.y", "load.F")
    with pytest.raises(TrimError, match="load.v"):
        s.trim()


def test_batch_equals_single_runs(spring_mass) -> None:
    s = spring_mass(B=10.0)
    ks = [400.0, 800.0, 1600.0]
    b = s.batch({"load.k_spring": ks}, t_end=0.3, n_points=31, threads=2)
    for i, k in enumerate(ks):
        single = s.simulate(t_end=0.3, n_points=31, params={"load.k_spring": k})
        np.testing.assert_allclose(b["load.x"][i], single["load.x"], rtol=1e-12, atol=1e-15)
        np.testing.assert_allclose(b["load.F_f"][i], single["load.F_f"], rtol=1e-12, atol=1e-12)
    assert b.params["load.k_spring"].tolist() == ks


def test_batch_runs_on_the_threads_asked_for_each_call(spring_mass) -> None:
    # The mapped integrator is cached; a second call with fewer threads must not reuse the first's threads.
    s = spring_mass(B=10.0)
    ks = [400.0, 800.0, 1600.0, 3200.0]
    s.batch({"load.k_spring": ks}, t_end=0.1, n_points=11, threads=2, method="cvodes")
    s.batch({"load.k_spring": ks}, t_end=0.1, n_points=11, threads=1, method="cvodes")
    maps = s.build()._batch_maps  # (integrator, runs, threads) -> mapped integrator; the model may be shared
    assert sorted(threads for _, runs, threads in maps if runs == 4) == [1, 2]


@pytest.mark.parametrize("method", ["cvodes", pytest.param("rodas3", marks=needs_compiler)])
def test_solver_failure_names_time_and_state(method) -> None:
    s = hs.System("runaway")
    s.add(c.Volume("vol", V=1e-5, beta_e=1e9, p0=1e5))
    s.add(c.Gain("pump", K=1e-6))  # flow proportional to pressure: exponential blow-up
    s.connect("vol.p", "pump.u")
    s.connect("pump.y", "vol.Q1")
    with pytest.raises(SolverError) as info:
        s.simulate(t_end=1.0, max_steps=200, method=method)
    msg = str(info.value)
    # where (CVODES: the output interval and its own time; compiled: the time it stopped), what (the state) and
    # why (budget, unstable mode)
    if method == "cvodes":
        assert "between t = 0 s and 0.001 s" in msg and "CVODES stopped at t = " in msg
    else:
        assert "(rodas3, compiled) failed: t = " in msg
    assert "step budget" in msg and "vol.p" in msg and "unstable" in msg


def test_c_code_generation_compiles(tmp_path) -> None:
    import shutil
    import subprocess

    model = hs.load_model("flight-simulator").build()
    path = model.generate_c(tmp_path / "fs_model.c")
    text = path.read_text()
    assert "int f(" in text and "int jac_x(" in text
    if shutil.which("gcc") is None:
        pytest.skip("no C compiler")
    subprocess.run(["gcc", "-c", "-O1", str(path), "-o", str(tmp_path / "fs_model.o")], check=True)
