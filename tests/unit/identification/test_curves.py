"""Least-squares fits to measured static curves (hydroservo.identification.curves), FerreiraND valve."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.data import parameter_set
from hydroservo.identification import Datasheet, fit_datasheet
from hydroservo.laws import pseudo_section as ps

DATASHEET = parameter_set("FerreiraND").table("datasheet")


def synthetic_curves(noise: float, seed: int = 1) -> tuple[dict[str, np.ndarray], Datasheet, dict[str, float]]:
    """Blocked-port and connected-port curves of the published variable model over +-6 %, with relative noise."""
    true = fit_datasheet(DATASHEET, "variable")
    ds = true.datasheet
    x = np.linspace(-0.06, 0.06, 49)
    A_p, A_n = true.sections(x)
    rng = np.random.default_rng(seed)
    curves = {
        "x_s": x,
        "P_L": ps.relative_load_pressure(A_p, A_n) + noise * rng.standard_normal(x.size),
        "q_lk": ps.leakage_blocked(A_p, A_n, ds.P_s) * (1 + noise * rng.standard_normal(x.size)),
        "Q_L": ps.load_flow_no_load(A_p, A_n, 2 * ds.P_n) * (1 + noise * rng.standard_normal(x.size)),
    }
    return curves, ds, true.params


def test_least_squares_fit_to_measured_curves() -> None:
    from hydroservo.identification import fit_curves

    curves, ds, true = synthetic_curves(0.0)
    exact = fit_curves(curves, ds, "variable")
    for k in ("k", "gamma", "x_t"):
        assert exact.params[k] == pytest.approx(true[k], rel=1e-6), k
    noisy, ds, _ = synthetic_curves(0.01)
    var = fit_curves(noisy, ds, "variable")
    assert var.params["k"] == pytest.approx(true["k"], rel=0.01)
    assert var.params["gamma"] == pytest.approx(true["gamma"], rel=0.01)
    assert abs(var.deviation["Q_n"]) < 1e-9  # nominal flow stays exact
    fix = fit_curves(noisy, ds, "fixed")  # the other family on the same data: misfit a few % at most
    assert max(v for k, v in fix.deviation.items() if k.startswith("rms_")) < 0.05
    assert abs(fix.sections(np.array([-1.0]))[0][0]) < 1e-3 * fix.sections(np.array([1.0]))[0][0]
