"""The engine: assembly, simulation against analytic solutions, trim, batch, errors."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import ModelError, ParameterError, SolverError, TrimError


def spring_mass(**kw: object) -> hs.System:
    s = hs.System("spring-mass")
    s.add(c.Mass("load", m=2.0, k_spring=800.0, x0=0.01, incline=0.0, **kw))
    return s


def test_undamped_spring_mass_matches_cosine() -> None:
    r = spring_mass().simulate(t_end=1.0, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(r["load.x"], 0.01 * np.cos(20.0 * r.t), atol=1e-9)


def test_damped_spring_mass_matches_analytic_solution() -> None:
    # m x'' + B x' + k x = 0, x(0) = x0, x'(0) = 0
    m, B, k, x0 = 2.0, 16.0, 800.0, 0.01
    r = spring_mass(B=B).simulate(t_end=1.0, rtol=1e-10, atol=1e-12)
    wn, zeta = np.sqrt(k / m), B / (2 * np.sqrt(k * m))
    wd = wn * np.sqrt(1 - zeta**2)
    exact = x0 * np.exp(-zeta * wn * r.t) * (np.cos(wd * r.t) + zeta * wn / wd * np.sin(wd * r.t))
    np.testing.assert_allclose(r["load.x"], exact, atol=1e-9)


def test_parameters_change_without_rebuild() -> None:
    s = spring_mass()
    model = s.build()
    r = s.simulate(t_end=0.1, params={"load.k_spring": "3.2 kN/m"})
    assert s.build() is model
    np.testing.assert_allclose(r["load.x"], 0.01 * np.cos(40.0 * r.t), atol=1e-6)


def closed_cylinder(**cyl: object) -> hs.System:
    """A cylinder with blocked ports, its rod pushed by a sinusoidal force."""
    s = hs.System("closed-cylinder")
    values: dict[str, object] = dict(A_A=2e-3, A_B=1.2e-3, V_A0=4e-4, V_B0=3e-4, beta_e=1.2e9, pA0=50e5, pB0=50e5)
    values.update(pressure_floor="none", **cyl)
    s.add(c.Cylinder("cyl", **values))
    s.add(c.Mass("load", m=20.0, incline=0.0, B=2000.0))
    s.add(c.Sine("force", unit="N", amplitude=4000.0, frequency=5.0))
    s.add(c.Sum("sum", unit="N", gain1=1.0, gain2=1.0))
    s.connect("force.y", "sum.u1")
    s.connect("cyl.F", "sum.u2")
    s.connect("sum.y", "load.F")
    s.connect("load.x", "cyl.x")
    s.connect("load.v", "cyl.v")
    s.add(c.Step("blocked", unit="m^3/s", amplitude=0.0))  # blocked ports: zero flow
    s.connect("blocked.y", "cyl.QA", "cyl.QB")
    return s


def test_closed_cylinder_conserves_mass() -> None:
    # Constant bulk modulus: d(ln V)/dt = -dp/dt / beta, so V exp(p/beta) is the oil
    # mass (over rho at zero pressure) and must stay constant in each chamber.
    s = closed_cylinder()
    r = s.simulate(t_end=0.6, n_points=601, rtol=1e-10, atol=1e-12)
    beta = 1.2e9
    VA = 4e-4 + 2e-3 * r["load.x"]
    VB = 3e-4 - 1.2e-3 * r["load.x"]
    mA = VA * np.exp(r["cyl.pA"] / beta)
    mB = VB * np.exp(r["cyl.pB"] / beta)
    assert np.ptp(r["load.x"]) > 1e-4  # the piston really moved
    np.testing.assert_allclose(mA, mA[0], rtol=1e-8)
    np.testing.assert_allclose(mB, mB[0], rtol=1e-8)


def test_internal_leakage_conserves_total_volume_flow() -> None:
    # With leakage A -> B and frozen volumes the leak leaves A and enters B:
    # (VA/beta) dpA/dt + (VB/beta) dpB/dt = -(A_A - A_B) v
    s = closed_cylinder(C_Li=2e-12, k_V=0.0)
    r = s.simulate(t_end=0.5, n_points=501, rtol=1e-10, atol=1e-12)
    beta = 1.2e9
    lhs = 4e-4 / beta * r["cyl.pA"] + 3e-4 / beta * r["cyl.pB"]
    rhs = lhs[0] - (2e-3 - 1.2e-3) * (r["load.x"] - r["load.x"][0])
    np.testing.assert_allclose(lhs, rhs, atol=1e-12)


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


def test_batch_equals_single_runs() -> None:
    s = spring_mass(B=10.0)
    ks = [400.0, 800.0, 1600.0]
    b = s.batch({"load.k_spring": ks}, t_end=0.3, n_points=31, threads=2)
    for i, k in enumerate(ks):
        single = s.simulate(t_end=0.3, n_points=31, params={"load.k_spring": k})
        np.testing.assert_allclose(b["load.x"][i], single["load.x"], rtol=1e-12, atol=1e-15)
        np.testing.assert_allclose(b["load.F_f"][i], single["load.F_f"], rtol=1e-12, atol=1e-12)
    assert b.params["load.k_spring"].tolist() == ks


def test_solver_failure_names_time_and_state() -> None:
    s = hs.System("runaway")
    s.add(c.Volume("vol", V=1e-5, beta_e=1e9, p0=1e5))
    s.add(c.Gain("pump", K=1e-6))  # flow proportional to pressure: exponential blow-up
    s.connect("vol.p", "pump.u")
    s.connect("pump.y", "vol.Q1")
    with pytest.raises(SolverError, match=r"failed at t = .* vol\.p"):
        s.simulate(t_end=1.0, max_steps=200)


def test_algebraic_loop_is_reported() -> None:
    s = hs.System("loop")
    s.add(c.Gain("a"))
    s.add(c.Gain("b"))
    s.add(c.Lag("lag"))
    s.connect("a.y", "b.u")
    s.connect("b.y", "a.u", "lag.u")
    with pytest.raises(ModelError, match="algebraic loop"):
        s.build()


def test_unconnected_input_is_reported() -> None:
    s = hs.System("open")
    s.add(c.Lag("lag"))
    with pytest.raises(ModelError, match="'lag.u'.*not connected"):
        s.build()


def test_bad_parameters_are_named() -> None:
    with pytest.raises(ParameterError, match=r"cyl\.A_A: '3 bar' has the wrong dimension"):
        c.Cylinder("cyl", A_A="3 bar")
    with pytest.raises(ParameterError, match=r"load\.m = '-2 kg'.*expected > 0 kg"):
        c.Mass("load", m="-2 kg")
    with pytest.raises(ParameterError, match=r"cyl\.beta.*expected > 0"):
        c.Cylinder("cyl", beta_e=-1.0)
    with pytest.raises(ParameterError, match="unknown parameter"):
        c.Mass("load", mass=3.0)
    with pytest.raises(ParameterError, match="expected one of constant, lee, eggerth"):
        c.Cylinder("cyl", bulk_modulus="magic")
    with pytest.raises(ModelError, match="has no output 'q'"):
        s = spring_mass()
        s.connect("load.q", "load.F")
    with pytest.raises(ModelError, match="different dimensions"):
        s = spring_mass()
        s.add(c.ConstantPressure("sup"))
        s.connect("sup.p", "load.F")


def test_bulk_modulus_options_and_volume_variation_run() -> None:
    for law in ("constant", "lee", "eggerth"):
        s = closed_cylinder(bulk_modulus=law, temperature=40.0, k_V=1.0)
        r = s.simulate(t_end=0.2)
        assert np.all(np.isfinite(r["cyl.pA"]))
    cold = closed_cylinder(bulk_modulus="eggerth", temperature=20.0).simulate(t_end=0.2)
    hot = closed_cylinder(bulk_modulus="eggerth", temperature=90.0).simulate(t_end=0.2)
    assert np.ptp(hot["load.x"]) > np.ptp(cold["load.x"])  # hot oil is softer (seed 001 Fig. 3.1): larger motion


def test_result_exports(tmp_path) -> None:
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
