"""The built-in position-servo against Hopsan's converged Position Servo (``hydroservo validate position-servo``).

The criterion (0.5 % of range) and the README's figures are the rows' (hydroservo/validation/hopsan.py). Here
the computed values are pinned loosely (a change of solver or law that moves them is noticed), and the verdicts
checked. The reference's own uncertainty is about 0.05 % of range; hydroservo lands at 0.0004 % (rodas3 at the default accuracy; CVODES there: 0.0021 %).
"""

from __future__ import annotations

import io

import numpy as np
import pytest

from hydroservo.data import reference_text


def test_position_servo_follows_hopsans_converged_result(validated) -> None:
    s = {c.row.key: c for c in validated("position-servo")}
    for key in ("x_dev", "x_dev_before_step", "pA_dev"):
        assert s[key].verdict == "reproduced", s[key].as_dict()
    # far inside the criterion: the laws are Hopsan's in the limit of a vanishing step
    assert s["x_dev"].computed < 0.01  # % of range (0.00036 % today, 3 um)
    assert s["pA_dev"].computed < 0.1  # % of range (0.02 % today)
    # the README's statements on the limit cycle, two figures each
    assert s["ps_min"].computed == pytest.approx(1.71, abs=0.01)
    assert s["cycle_f"].computed == pytest.approx(23.0, abs=0.2)
    assert s["cycle_pp"].computed == pytest.approx(25.3, abs=0.3)
    # hydroservo's default cylinder floor puts the cycle elsewhere: the issue measured 14 % of range by hand
    assert s["x_dev_check_valves"].computed == pytest.approx(14.1, abs=0.5)


def test_the_reference_is_the_one_hopsan_wrote() -> None:
    # the shipped copy is Hopsan's file: 601 rows every 5 ms, x from 0 to 0.81 m, its README beside it
    ref = np.genfromtxt(io.StringIO(reference_text("hopsan_position_servo.csv")), delimiter=",", skip_header=1)
    assert ref.shape == (601, 7)
    assert ref[1, 0] - ref[0, 0] == pytest.approx(0.005) and ref[-1, 0] == pytest.approx(3.0)
    assert np.ptp(ref[:, 1]) == pytest.approx(0.810381, abs=1e-6)
    assert "Richardson" in reference_text("README.md")
