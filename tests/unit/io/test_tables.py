"""Time tables read from CSV files (hydroservo.io.tables) feeding a table source."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import ParameterError
from hydroservo.io import read_time_table


def test_table_source_from_csv(tmp_path) -> None:
    path = tmp_path / "u.csv"
    path.write_text("t,volts\n0,0\n1,2\n2,2\n")
    s = hs.System("table")
    s.add(c.Table("u", *read_time_table(path, "volts"), unit="V"))
    s.add(c.Lag("lag", unit="V"))
    s.connect("u.y", "lag.u")
    r = s.simulate(t_eval=[0.0, 0.5, 1.5])
    np.testing.assert_allclose(r["u.y"], [0.0, 1.0, 2.0])
    with pytest.raises(ParameterError, match="'amps' is not a column"):
        c.Table("u", *read_time_table(path, "amps"))
