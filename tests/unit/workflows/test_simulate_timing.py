"""The time a run prints keeps the compile of its model apart: a first run (an empty cache folder) compiles the
model to C, which takes seconds and is not integration."""

from __future__ import annotations

import re

import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.system.native import cache_entries, has_compiler
from hydroservo.workflows import simulate


def _spring() -> hs.System:
    s = hs.System("spring", t_end=0.1)
    s.add(c.Mass("load", m=2.0, k_spring=800.0, x0=0.01, incline=0.0))
    return s


@pytest.mark.skipif(not has_compiler(), reason="the compiled method needs a C compiler")
def test_a_cold_run_shows_its_compile_apart_from_its_integration(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("HYDROSERVO_CACHE", str(tmp_path))
    assert cache_entries() == []
    cold = simulate.run(_spring(), method="rodas3", write="none")
    assert len(cache_entries()) == 1  # it was compiled in this run
    line = cold.lines()[0]
    found = re.fullmatch(r"simulated 'spring' for 0\.1 s in ([\d.]+) ms \(compile/load ([\d.]+) ms, integration "
                         r"([\d.]+) ms, \d+ steps, rodas3 compiled\)", line)
    assert found, line
    total, compile_ms, integration = map(float, found.groups())
    assert compile_ms + integration <= total + 0.2  # parts of the whole, each said
    assert cold.to_dict()["solver"]["compile_load_wall_time_s"] == pytest.approx(compile_ms / 1e3, abs=1e-4)
    assert cold.solver_stats()["compile_load_wall_time_s"] == cold.compile_time
    warm = simulate.run(_spring(), method="cvodes", write="none")  # nothing compiled: nothing said
    assert "compile" not in warm.lines()[0] and "compile_load_wall_time_s" not in warm.to_dict()["solver"]
