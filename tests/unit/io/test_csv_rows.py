"""One way to read CSV rows for every reader: whole-line comments and blank lines out, a '#' inside a line kept."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hydroservo.io.results import read_csv, write_table


def test_a_result_file_with_comment_lines_and_hopsan_names_reads_back(tmp_path: Path) -> None:
    # write_table puts '# ' comment lines first; read_csv used to take the first of them for the header
    path = write_table(tmp_path / "r.csv", ["t [s]", "Servo#PA#Pressure [bar]"], [[0.0, 1.0], [0.5, 2.0], [1.0, 3.0]],
                       comments=["from the rig, bench 3", "pressures gauge"])
    assert path.read_text().startswith("# from the rig")
    result = read_csv(path)
    np.testing.assert_allclose(result["Servo#PA#Pressure"], [1e5, 2e5, 3e5])
    assert result.units["Servo#PA#Pressure"] == "Pa"
