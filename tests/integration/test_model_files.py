"""Model files end to end: a built-in and a user model exported to TOML, read back, simulated identically."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import hydroservo as hs
from hydroservo.io import model_to_toml, read_model


def test_round_trip_builtin_and_user_model(tmp_path: Path, valve_cylinder_file: Path) -> None:
    for system in (hs.load_model("flight-simulator"), read_model(valve_cylinder_file)):
        path = tmp_path / "exported.toml"
        path.write_text(model_to_toml(system))
        again = read_model(path)
        r1, r2 = system.simulate(), again.simulate()
        for name in r1.names:
            np.testing.assert_array_equal(r1[name], r2[name])
