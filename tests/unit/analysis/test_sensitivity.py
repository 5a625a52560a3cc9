"""Sensitivity studies: Sobol indices of the Ishigami function against their known values, Morris effects of a
linear function, one-at-a-time families, and the runs behind them (failures kept apart, resume, Dask)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.analysis.campaign import run_design
from hydroservo.analysis.metrics import Metric, parse_metric
from hydroservo.analysis.sensitivity import custom_metric, morris, one_at_a_time, sobol
from hydroservo.components.base import Component, Output, Param
from hydroservo.errors import ParameterError
from hydroservo.io import RunStore, read_runs


class Ishigami(Component):
    """y = sin x1 + a sin^2 x2 + b x3^4 sin x1 ([IshigamiHomma1990]); no states: each run is its output."""

    PARAMETERS = {
        "x1": Param(0.0, "", "first input"),
        "x2": Param(0.0, "", "second input"),
        "x3": Param(0.0, "", "third input"),
        "a": Param(7.0, "", "a"),
        "b": Param(0.1, "", "b"),
    }
    OUTPUTS = {"y": Output("", "the function")}

    def output_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        from hydroservo import backend as bk

        s1 = bk.sin(p["x1"])
        return {"y": s1 + p["a"] * bk.sin(p["x2"]) ** 2 + p["b"] * p["x3"] ** 4 * s1}


class Linear(Component):
    """y = 2 x1 + 0.5 x2 + 0 x3."""

    PARAMETERS = {k: Param(0.0, "", k) for k in ("x1", "x2", "x3")}
    OUTPUTS = {"y": Output("", "the function")}

    def output_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        return {"y": 2.0 * p["x1"] + 0.5 * p["x2"] + 0.0 * p["x3"]}


def function_system(comp: Component) -> hs.System:
    s = hs.System("f", t_end=1.0)
    s.add(comp)
    return s


PI = (-np.pi, np.pi)
ISHIGAMI = {"f.x1": PI, "f.x2": PI, "f.x3": PI}


def test_sobol_indices_of_the_ishigami_function() -> None:
    """a = 7, b = 0.1: S1 = (0.3139, 0.4424, 0), ST = (0.5576, 0.4424, 0.2437) (Ishigami & Homma 1990; the
    closed forms as in Saltelli et al., Global Sensitivity Analysis: The Primer, 2008, section 4.9).

    Tolerance 0.05: with n = 2048 (10 240 runs) the estimators' bootstrap half-widths are 0.02-0.04, so the
    estimates fall within about 0.05 of the exact values; the half-widths are checked to cover them too.
    """
    study = sobol(function_system(Ishigami("f")), ISHIGAMI, 2048, metrics=["final(f.y)"], n_points=2)
    assert study.runs.stats["runs"] == 2048 * 5 and study.runs.stats["failed"] == 0
    got = study.indices.set_index("parameter")
    exact_S1 = {"f.x1": 0.3139, "f.x2": 0.4424, "f.x3": 0.0}
    exact_ST = {"f.x1": 0.5576, "f.x2": 0.4424, "f.x3": 0.2437}
    for name in ISHIGAMI:
        assert got.loc[name, "S1"] == pytest.approx(exact_S1[name], abs=0.05), name
        assert got.loc[name, "ST"] == pytest.approx(exact_ST[name], abs=0.05), name
        assert abs(got.loc[name, "ST"] - exact_ST[name]) < 2 * got.loc[name, "ST_conf"] + 0.01, name
    # repeatable: the same seed gives the same indices and intervals
    again = sobol(function_system(Ishigami("f")), ISHIGAMI, 256, metrics=["final(f.y)"], n_points=2, seed=3)
    twice = sobol(function_system(Ishigami("f")), ISHIGAMI, 256, metrics=["final(f.y)"], n_points=2, seed=3)
    assert again.indices.equals(twice.indices)


def test_morris_effects_of_a_linear_function_are_its_slopes() -> None:
    """On [0, 1] every elementary effect of y = 2 x1 + 0.5 x2 is its slope: mu* = (2, 0.5, 0), sigma = 0."""
    ranges = {f"f.x{i}": (0.0, 1.0) for i in (1, 2, 3)}
    study = morris(function_system(Linear("f")), ranges, 10, metrics=["final(f.y)"], n_points=2)
    got = study.indices.set_index("parameter")
    np.testing.assert_allclose(got["mu_star"].to_numpy(), [2.0, 0.5, 0.0], atol=1e-9)
    np.testing.assert_allclose(got["sigma"].to_numpy(), 0.0, atol=1e-9)
    assert study.runs.stats["runs"] == 10 * 4


def drive() -> hs.System:
    """A mass pushed by a force step: final position F/k, a quick test system with states."""
    s = hs.System("spring", t_end=2.0)
    s.add(c.Mass("m", m=1.0, B=20.0, k_spring=100.0, incline=0.0))
    s.add(c.Step("f", unit="N", amplitude=10.0))
    s.connect("f.y", "m.F_ext")
    return s


def test_one_at_a_time_levels_parameters_and_options() -> None:
    s = drive()
    study = one_at_a_time(s, {"m.k_spring": ["50 N/m", "100 N/m", "200 N/m"]}, metrics=["final(m.x)", "peak(m.v)"],
                          signals=["m.x"], t_end=2.0)
    final = study.table["final(m.x) [m]"].to_numpy()
    np.testing.assert_allclose(final, [10 / 50, 10 / 100, 10 / 200], rtol=2e-2)  # settled within 2 s (tau 0.1-0.4 s)
    assert study.levels["m.k_spring"] == ["50 N/m", "100 N/m", "200 N/m"]
    assert study.responses["m.k_spring"][0]["m.x"].shape == (301,)
    arm = hs.load_model("robot-arm")
    laws = one_at_a_time(arm, {"cyl.bulk_modulus": ["lee", "constant"]}, metrics=["final(x_mm)"], t_end=0.3, n_points=31)
    assert list(laws.table["level"]) == ["lee", "constant"] and (laws.table["status"] == "ok").all()
    with pytest.raises(ParameterError, match="option value 'air'"):
        one_at_a_time(arm, {"cyl.bulk_modulus": ["air"]})


def test_failed_runs_are_kept_apart_and_the_rest_is_analysed(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """A run refused by a parameter check fails with its reason; the others are measured; its metric has no
    indices (the estimators need every point), said in a note."""
    s = drive()
    runs = run_design(s, {"m.m": [1.0, -1.0, 2.0]}, [parse_metric("final(m.x)")])
    assert list(runs.table["status"]) == ["ok", "failed", "ok"]
    assert "m.m" in runs.table.loc[1, "reason"] and np.isnan(runs.values()[1, 0])
    assert runs.values()[0, 0] == pytest.approx(0.1, rel=2e-2)
    study = sobol(s, {"m.m": (-0.5, 2.0), "m.B": (10.0, 30.0)}, 8, metrics=["final(m.x)"])
    assert study.runs.stats["failed"] > 0 and study.indices["S1"].isna().all()
    assert "not estimated" in study.notes[0]


def test_runs_are_written_as_they_arrive_and_a_study_resumes(tmp_path) -> None:  # type: ignore[no-untyped-def]
    s = drive()
    design = {"m.k_spring": np.linspace(50.0, 200.0, 10)}
    metrics = [parse_metric("final(m.x)")]
    store = RunStore(tmp_path / "runs", {"study": 1})
    first = run_design(s, design, metrics, chunk=4, store=store)
    assert len(store.parts()) == 3 and first.stats["run_now"] == 10
    store.parts()[1].unlink()  # as if interrupted before the second chunk was written
    seen: list[tuple[int, int]] = []
    again = run_design(s, design, metrics, chunk=4, store=RunStore(tmp_path / "runs", {"study": 1}),
                       progress=lambda done, failed, total, elapsed: seen.append((done, total)))
    assert again.stats["run_now"] == 4 and again.stats["resumed"] == 6 and seen == [(10, 10)]
    np.testing.assert_array_equal(again.values(), first.values())
    assert read_runs(tmp_path / "runs").shape[0] == 10
    with pytest.raises(ParameterError, match="another study"):
        RunStore(tmp_path / "runs", {"study": 2})


def test_custom_metric_and_bad_metrics() -> None:
    s = drive()
    energy = custom_metric("work", lambda t, sig: float(np.trapezoid(sig["m.v"] ** 2, t)), "m^2/s")
    runs = run_design(s, {"m.B": [10.0, 30.0]}, [energy, parse_metric("mean(m.x, 1 s, 2 s)")])
    assert runs.values()[0, 0] > runs.values()[1, 0] > 0  # more damping, less motion
    assert isinstance(runs.metrics[0], Metric)
    for bad, pattern in [("final(m.q)", "not a state"), ("median(m.x)", "unknown kind"), ("final m.x", "expected KIND"),
                         ("mean(m.x, 1 s)", "needs the window"), ("at(m.x, 5 s)", "within the run")]:
        with pytest.raises(ParameterError, match=pattern):
            parse_metric(bad, s.build().units, 2.0)


@pytest.mark.slow
def test_a_study_on_a_local_dask_cluster_gives_the_local_numbers() -> None:
    """Two worker processes, chunks as tasks: the same runs, the same metrics, the same indices."""
    distributed = pytest.importorskip("distributed")
    arm = hs.load_model("robot-arm")
    ranges = {"valve.c_v": ("1e-4 m^2/s/Pa^0.5", "2e-4 m^2/s/Pa^0.5"), "spool.tau": ("20 ms", "40 ms"),
              "load.m": ("15 kg", "35 kg")}
    local = sobol(arm, ranges, 16, chunk=20, t_end=0.8, n_points=81)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            remote = sobol(arm, ranges, 16, chunk=20, t_end=0.8, n_points=81, scheduler=client)
    assert remote.runs.stats["where"] == "dask" and remote.runs.stats["chunks"] == 4
    np.testing.assert_array_equal(remote.runs.values(), local.runs.values())
    assert remote.indices.equals(local.indices)


def test_a_run_the_solver_gives_up_on_is_tried_again_tighter() -> None:
    """A hundred solver steps are too few for a light, stiff spring ringing for 2 s (3000 cycles); the retry (ten
    times tighter, a million steps) solves it and says so; a run refused for its parameters stays failed."""
    s = drive()
    s.set("m.k_spring", 1e6)
    runs = run_design(s, {"m.m": [0.01, -1.0]}, [parse_metric("final(m.x)")], max_steps=100, n_points=3)
    assert list(runs.table["status"]) == ["ok", "failed"]
    assert runs.table.loc[0, "reason"].startswith("solved at rtol 1e-07 after:")
    assert np.isfinite(runs.values()[0, 0])


def test_default_step_metrics_measure_the_loads_position_from_the_commands_step() -> None:
    # the first plotted signal of flight-simulator is its command (vi, a step): its rise time is NaN, so the
    # default step metrics took it before; they measure the load's position, and from the step's time
    import hydroservo as hs
    from hydroservo.analysis.metrics import default_metrics

    fs = hs.load_model("flight-simulator")
    names = [m.name for m in default_metrics(fs, fs.t_end)]
    assert "rise_time(y)" in names and not any(n.endswith("(vi)") and "time" in n for n in names)
    ps = hs.load_model("position-servo")
    assert "overshoot(load.x,1s)" in [m.name for m in default_metrics(ps, ps.t_end)]
