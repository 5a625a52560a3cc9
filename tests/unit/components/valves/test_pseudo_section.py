"""The pseudo-section valve component of FerreiraND (hydroservo.components.valves.pseudo_section)."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.components import ConstantPressure, PseudoSectionValve, Step
from hydroservo.laws import pseudo_section as ps


def test_component_flows_are_the_published_law() -> None:
    s = hs.System("valve")
    s.add(Step("xs", amplitude=0.03))
    s.add(ConstantPressure("supply", p="70 bar"))
    s.add(Step("pA", unit="Pa", amplitude="30 bar"))
    s.add(Step("pB", unit="Pa", amplitude="45 bar"))
    s.add(PseudoSectionValve("valve", structure="fixed", p_tr=0.0))
    for src, dst in (("xs.y", "valve.xs"), ("supply.p", "valve.pS"), ("pA.y", "valve.pA"), ("pB.y", "valve.pB")):
        s.connect(src, dst)
    res = s.simulate(t_end=1e-3, n_points=2)
    comp = s["valve"]
    params = {k: comp.values[k] for k in ps.PARAMETER_NAMES["fixed"]}
    A_p, A_n = ps.pseudo_sections(np.array(0.03), "fixed", params)
    expected = ps.matched_valve_flows(A_p, A_n, 70e5, 0.0, 30e5, 45e5)
    for name, q in zip(("QA", "QB", "QS", "QT"), expected):
        assert res.get(f"valve.{name}")[-1] == pytest.approx(float(q), rel=1e-12)
