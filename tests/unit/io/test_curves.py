"""Bench curve files (hydroservo.io.curves): round trip and bad files."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hydroservo.analysis.static_bench import Bench, bench_curves
from hydroservo.components import StagedSlotValve
from hydroservo.errors import ParameterError
from hydroservo.io import read_bench_curves, write_bench_curves


def test_bench_curve_files_round_trip_and_bad_files(
    tmp_path: Path, aerospace_valve: StagedSlotValve, aerospace_bench: Bench
) -> None:
    bench = aerospace_bench
    curves = bench_curves(aerospace_valve, -15.0, bench, n=41)
    paths = write_bench_curves(curves, tmp_path)
    back = read_bench_curves(paths)
    assert back.temperature == -15.0 and back.bench.P_s == pytest.approx(bench.P_s)
    np.testing.assert_allclose(back.P_1, curves.P_1, rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(back.Q_lk, curves.Q_lk, rtol=1e-12)
    bad = tmp_path / "bad.csv"
    bad.write_text(paths[0].read_text().replace("# temperature = -15.0 degC\n", ""))
    with pytest.raises(ParameterError, match="missing '# temperature"):
        read_bench_curves([bad])
    bad.write_text(paths[0].read_text().replace("Q_L [L/min]", "Q_L"))
    with pytest.raises(ParameterError, match=r"expected a unit in brackets"):
        read_bench_curves([bad])
    other = tmp_path / "other.csv"
    other.write_text(paths[1].read_text().replace("temperature = -15.0", "temperature = 20"))
    with pytest.raises(ParameterError, match="one temperature"):
        read_bench_curves([paths[0], other])
