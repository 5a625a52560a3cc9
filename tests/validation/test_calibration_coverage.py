"""The calibration's 95 % intervals cover the truth as often as 95 % intervals should.

Forty records of the stepped robot arm (Efe2014 Table 5.1's rates, 0.05 bar and 0.02 mm of noise), each made
with ARM_TRUTH and its own noise draw, are each calibrated for the five parameters (spool time constant, flow
coefficient, leakage, viscous and Coulomb friction) from the published arm. If the intervals are honest, each
parameter's interval holds the truth in about 38 of 40 fits; the binomial distribution (n 40, p 0.95) puts
33..40 at 99.9 %, the range the issue asks for.
"""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.identification.calibration import calibrate

FIVE = ["spool.tau", "valve.c_v", "cyl.C_Li", "load.B", "load.F_c0"]
NOISE = {"cyl.pA": "0.05 bar", "cyl.pB": "0.05 bar", "load.x": "0.02 mm"}
DRAWS = 40


@pytest.mark.slow
def test_intervals_cover_the_truth(stepped_arm, make_arm_record, arm_truth) -> None:
    covered = np.zeros(len(FIVE), dtype=int)
    z = []
    for seed in range(100, 100 + DRAWS):
        record = make_arm_record(seed)
        cal = calibrate(stepped_arm(), [record], FIVE, inputs=["command.y"], noise=NOISE)
        assert cal.success, (seed, cal.message)
        truth = np.array([arm_truth[n] for n in FIVE])
        covered += (cal.ci95[:, 0] <= truth) & (truth <= cal.ci95[:, 1])
        z.append((cal.values - truth) / cal.stderr)
    print("covered:", dict(zip(FIVE, covered.tolist())))
    print("mean z:", np.round(np.mean(z, axis=0), 2), "sd z:", np.round(np.std(z, axis=0), 2))
    assert np.all((33 <= covered) & (covered <= DRAWS)), dict(zip(FIVE, covered.tolist()))
