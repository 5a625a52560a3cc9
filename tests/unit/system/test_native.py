"""Compiled models (hydroservo.system.native): simulate(method=...) against CVODES, the disk cache (reuse,
damage, concurrent builds), and names that reach C only as escaped strings.

Every test builds into a cache folder of its own (``HYDROSERVO_CACHE``), so the user's cache is untouched and
each build is a real one. Deviations are relative to each signal's range over the run, against CVODES at
rtol 1e-10 (about 1e-9 of range).
"""

from __future__ import annotations

import subprocess
import sys
import textwrap
import warnings
from pathlib import Path

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import ParameterError, SolverError
from hydroservo.system import native
from hydroservo.system.native import cache_folder, compiled, has_compiler, model_sources

if not has_compiler():
    pytest.skip("no C compiler", allow_module_level=True)


@pytest.fixture(autouse=True)
def own_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    folder = tmp_path / "cache"
    monkeypatch.setenv("HYDROSERVO_CACHE", str(folder))
    return folder


def _spring(name: str = "spring") -> hs.System:
    s = hs.System(name, t_end=1.0)
    s.add(c.Mass("load", m=2.0, k_spring=800.0, x0=0.01, incline=0.0, B=4.0))
    return s


@pytest.mark.parametrize("method", ["rodas3", "ros23", "dopri5"])
def test_simulate_with_a_compiled_method_agrees_with_cvodes(method: str) -> None:
    """servo-solenoid-cylinder at accuracy 1e-4: every plotted signal within 1e-3 of its range of CVODES'
    (ros23 deviates most, 5.9e-5 measured), outputs and plausibility checks read as for CVODES."""
    system = hs.load_model("servo-solenoid-cylinder")
    ref = system.simulate(rtol=1e-10, atol=1e-12, method="cvodes")
    run = system.simulate(method=method)
    assert run.stats["method"] == method and run.stats["nsteps"] > 0
    for name in (n for panel in system.default_panels() for n in panel):
        assert np.max(np.abs(run[name] - ref[name])) <= 1e-3 * np.ptp(ref[name]), name
    assert run.warnings == ref.warnings


def test_an_unknown_method_is_refused_with_the_choices() -> None:
    with pytest.raises(ParameterError, match="method = 'euler': expected one of auto, cvodes, rodas3, ros23, dopri5"):
        _spring().simulate(method="euler")


def test_a_failing_compiled_run_names_the_time_and_the_state() -> None:
    with pytest.raises(SolverError, match=r"\(dopri5, compiled\) failed: t = .* step budget of 100 steps"):
        _spring().simulate(method="dopri5", max_steps=100, rtol=1e-12, atol=1e-14)


def test_the_cache_is_reused_across_processes_and_a_damaged_entry_is_rebuilt(own_cache: Path) -> None:
    model = _spring().build()
    sources = model_sources(model, "hs_cache_test")
    first = compiled(sources)
    assert first.parent.parent == own_cache / "c" and cache_folder() == own_cache
    stamp = first.stat().st_mtime_ns
    assert compiled(sources) == first and first.stat().st_mtime_ns == stamp  # reused, not rebuilt
    for damage in (lambda b: b[: len(b) // 2], lambda b: b[:100] + b"\x00" + b[101:]):  # truncated, altered
        first.write_bytes(damage(first.read_bytes()))
        again = compiled(sources)
        assert again == first and (again.parent / "sha256").read_text().strip() == native._digest(again)
        assert np.isfinite(_spring().simulate(method="ros23")["load.x"]).all()
    other = model_sources(model, "hs_cache_other")  # other sources: another entry
    assert compiled(other).parent != first.parent


def test_two_processes_building_one_model_at_once_both_succeed(own_cache: Path) -> None:
    script = textwrap.dedent(
        """
        import hydroservo as hs
        r = hs.load_model("flight-simulator").simulate(method="ros23", n_points=11)
        print(float(r["y"][-1]))
        """
    )
    runs = [subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True) for _ in range(2)]
    outputs = [run.communicate(timeout=120)[0] for run in runs]
    assert [run.returncode for run in runs] == [0, 0]
    assert outputs[0] == outputs[1] and float(outputs[0])
    entries = [p for p in (own_cache / "c").iterdir() if not p.name.startswith(".")]
    assert len(entries) == 1 and not [p for p in (own_cache / "c").iterdir() if p.name.startswith(".build")]


def test_hostile_names_reach_c_only_as_strings() -> None:
    """A model name with a comment terminator, quotes, backslashes, a trigraph and a newline, and an alias
    described in C syntax (names themselves must be identifiers): the sources compile, nothing of them is
    code, and the run is the interpreted one's."""
    hostile = 'evil */ #include "x.h" \\ ??/ \n "quoted" /*'
    system = _spring(hostile)
    system.alias("y", "load.x", "m", 'y"); system("rm -rf /"); /* */ with "quotes" \\')
    sources = model_sources(system.build(), "hs_hostile")
    assert "#include \"x.h\"" not in sources.files["hs_hostile.c"].replace('\\"', "")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        run = system.simulate(method="ros23", rtol=1e-8)
    ref = system.simulate(rtol=1e-10, atol=1e-12, method="cvodes")
    assert "system(" not in sources.files["hs_hostile.c"] and "*/ #include" not in sources.files["hs_hostile.c"]
    assert np.max(np.abs(run["y"] - ref["load.x"])) < 1000 * 1e-8 * 0.02  # ros23's global error: test_adaptive


def test_a_batch_with_a_compiled_method_is_its_runs_on_threads() -> None:
    """Each run of a compiled batch is the single run with the same method (the same C code, to the last bit),
    on two threads as on one; a run that fails keeps its reason and leaves the others."""
    system = _spring()
    masses = [1.0, 2.0, 3.0]
    one = system.batch({"load.m": masses}, 1.0, n_points=51, method="dopri5", threads=1)
    two = system.batch({"load.m": masses}, 1.0, n_points=51, method="dopri5", threads=2)
    for k, m in enumerate(masses):
        single = system.simulate(1.0, params={"load.m": m}, n_points=51, method="dopri5")
        np.testing.assert_array_equal(one["load.x"][k], single["load.x"])
        np.testing.assert_array_equal(two["load.x"][k], single["load.x"])
    assert one.stats["method"] == "dopri5" and not one.failed
    starved = system.batch({"load.m": masses}, 1.0, n_points=51, method="dopri5", max_steps=100, rtol=1e-12)
    assert sorted(starved.failed) == [0, 1, 2] and "step budget" in starved.failed[0]
    assert np.isnan(starved["load.x"]).all()


def test_without_a_compiler_a_compiled_method_is_refused_with_the_way_out(monkeypatch: pytest.MonkeyPatch) -> None:
    def no_compiler() -> list[str]:
        raise ParameterError("C compiler: none found (CC is not set, and none of cc, gcc, clang is on PATH)")

    monkeypatch.setattr(native, "compiler", no_compiler)
    with pytest.raises(ParameterError, match=r"method = 'ros23' runs the model compiled to C.*method='cvodes' needs none"):
        _spring("no-compiler").simulate(method="ros23")
    assert np.isfinite(_spring("no-compiler").simulate(method="cvodes")["load.x"]).all()  # CVODES needs none


def _stepped_lag() -> hs.System:
    """A unit step at t = 0.3037 s into a lag of 50 ms: y = 1 - exp(-(t - 0.3037)/0.05) after the step."""
    s = hs.System("stepped-lag", t_end=1.0)
    s.add(c.Step("u", t_step=0.3037))
    s.add(c.Lag("lag", tau=0.05))
    s.connect("u.y", "lag.u")
    return s


@pytest.mark.parametrize("method", ["dopri5", "ros23", "rodas3"])
def test_an_event_ends_a_step_at_the_kink(method: str) -> None:
    """The step source declares its time as a switch: the solver finds the crossing and ends a step just past
    it, so the solution is the closed form to the tolerance's level right after the step, at a loose tolerance
    where a step straddling the jump would be off by the jump's share of it."""
    system = _stepped_lag()
    assert system.build().assembly.switches[0] == ["u.step"]
    times = np.linspace(0.0, 1.0, 2001)
    run = system.simulate(t_eval=times, method=method, accuracy=1e-2)
    exact = np.where(times < 0.3037, 0.0, 1.0 - np.exp(-(times - 0.3037) / 0.05))
    assert run.stats["nevents"] == 1
    assert np.max(np.abs(run["lag.y"] - exact)) < 1e-4  # measured 1.6e-5 (dopri5), 5.4e-5 (ros23)
    across = system.simulate(t_eval=times, method=method, accuracy=1e-2, events=False)
    assert across.stats["nevents"] == 0 and np.isfinite(across["lag.y"]).all()


def test_auto_runs_rodas3_where_the_model_compiles() -> None:
    run = _spring("auto").simulate()
    assert run.stats["method"] == "rodas3" == hs.system.integration.AUTO_METHOD


def test_without_a_compiler_auto_runs_cvodes_and_says_so_once(monkeypatch: pytest.MonkeyPatch) -> None:
    from hydroservo.errors import InterpretedWarning
    from hydroservo.system import model as model_module

    def no_compiler() -> list[str]:
        raise ParameterError("C compiler: none found (CC is not set, and none of cc, gcc, clang is on PATH)")

    monkeypatch.setattr(native, "compiler", no_compiler)
    monkeypatch.setattr(model_module, "_INTERPRETED_SAID", model_module.threading.Event())
    with pytest.warns(InterpretedWarning, match="CVODES in CasADi's interpreter.*none found.*Install a C compiler"):
        first = _spring("auto-no-compiler").simulate()
    with warnings.catch_warnings():
        warnings.simplefilter("error", InterpretedWarning)  # said once a process
        second = _spring("auto-no-compiler-2").simulate()
    assert first.stats["method"] == second.stats["method"] == "cvodes"


@pytest.mark.parametrize("method", ["rodas3", "ros23", "dopri5"])
def test_a_square_wave_is_not_stepped_over(method: str) -> None:
    """A 10 Hz square wave into a 5 ms lag, held at its level long enough for the steps to grow past a
    half-period: each edge is seen (an event) and the lag follows it, as CVODES has it at rtol 1e-10, within
    1e-3 of the range at accuracy 1e-3. Before the square wave declared its edges and output times ended steps,
    rodas3 stepped from one level to the same level a period later and missed both edges between (the
    two-stage servovalve's 25 % square wave, tests/unit/components/valves/test_two_stage.py)."""
    s = hs.System("square-into-lag", t_end=0.3)
    s.add(c.Square("u", frequency=10.0))
    s.add(c.Lag("lag", tau=0.005))
    s.connect("u.y", "lag.u")
    ref = s.simulate(n_points=301, rtol=1e-10, atol=1e-12, method="cvodes")
    run = s.simulate(n_points=301, accuracy=1e-3, method=method)
    assert run.stats["nevents"] == 5  # the edges at 0.05, 0.1, ..., 0.25 s
    assert np.max(np.abs(run["lag.y"] - ref["lag.y"])) < 1e-3 * np.ptp(ref["lag.y"])


@pytest.mark.parametrize("method", ["rodas3", "dopri5"])
def test_output_times_a_hair_apart_are_one_step_end(method: str) -> None:
    """Output times closer than any step can be (a grid merged from two sources: 0.015 and the next float after
    it) end one step and share its state, rather than asking for a step of 1e-18 s."""
    t = 0.015
    grid = [0.0, t, float(np.nextafter(t, 1.0)), 0.03]
    run = _spring("hair").simulate(t_eval=grid, method=method)
    assert run["load.x"][1] == run["load.x"][2] and np.isfinite(run["load.x"]).all()


def test_auto_runs_cvodes_on_a_large_model() -> None:
    """Past AUTO_MAX_STATES states a Rosenbrock step (a dense Jacobian evaluated and factorised every step) costs
    more than CVODES' (bench_growth: 0.89x at 30 states): auto runs CVODES there, and compiles nothing."""
    from hydroservo.system.integration import AUTO_MAX_STATES

    s = hs.System("many-masses", t_end=0.1)
    for k in range(AUTO_MAX_STATES // 2 + 1):
        s.add(c.Mass(f"m{k}", m=1.0 + k, k_spring=800.0, x0=0.01, incline=0.0, B=4.0))
    assert s.build().nx > AUTO_MAX_STATES
    assert s.simulate(n_points=11).stats["method"] == "cvodes"
    built = cache_folder() / "c"
    assert not built.exists() or not any(built.iterdir())
