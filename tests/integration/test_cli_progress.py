"""Progress of the long commands (tqdm on stderr): stages by name with their time, counted work as a bar;
nothing under --json or when stderr is not a terminal; ``batch(progress=True)`` in the API."""

from __future__ import annotations

import argparse

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.cli.progress import Bars, progress_bars


def test_bars_show_each_stage_and_the_counted_work(capsys: pytest.CaptureFixture[str]) -> None:
    bars = Bars(enabled=True)
    bars("running the static tests")
    bars("running the bode tests")
    for done in (1, 3, 10):
        bars.count(done, 10)
    bars.runs(20, 2, 40, 1.0)  # a study's runs, with the failures beside them
    bars.close()
    err = capsys.readouterr().err
    assert "running the static tests: 00:00" in err and "running the bode tests" in err
    assert "3/10" in err and "10/10" in err and "20/40" in err and "failed=2" in err


def test_bars_are_silent_under_json_or_off_a_terminal(capsys: pytest.CaptureFixture[str]) -> None:
    for bars in (progress_bars(argparse.Namespace(json=True)), progress_bars(argparse.Namespace(json=False))):
        bars("running the static tests")  # stderr is captured here: not a terminal
        bars.count(5, 10)
        bars.close()
    assert capsys.readouterr().err == ""


def test_a_batch_shows_a_bar_when_asked(capsys: pytest.CaptureFixture[str]) -> None:
    s = hs.System("springs", t_end=0.1)
    s.add(c.Mass("load", m=2.0, k_spring=800.0, x0=0.01, incline=0.0, B=4.0))
    runs = s.batch({"load.m": np.linspace(1.0, 3.0, 12)}, n_points=11, progress=True)
    assert len(runs) == 12 and runs.ok.all()
    err = capsys.readouterr().err
    assert "springs: runs" in err and "12/12" in err
    s.batch({"load.m": np.linspace(1.0, 3.0, 12)}, n_points=11)  # no bar unless asked
    assert capsys.readouterr().err == ""
