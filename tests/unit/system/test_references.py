"""System.references(): the bibliography entries a system draws on, as its assembly uses them."""

from __future__ import annotations

import hydroservo as hs
from hydroservo import components as c


def _cylinder(law: str) -> hs.System:
    s = hs.System("cyl")
    s.add(c.ConstantPressure("supply"))
    s.add(c.Tank("tank"))
    s.add(c.Orifice("inlet"))
    s.add(c.Orifice("out"))
    s.add(c.Cylinder("cyl", bulk_modulus=law))
    s.add(c.Mass("load", m=10.0))
    s.connect("supply.P", "inlet.A")
    s.connect("inlet.B", "cyl.A")
    s.connect("cyl.B", "out.A")
    s.connect("out.B", "tank.P")
    s.connect("cyl.F", "load.F")
    s.connect("load.x", "cyl.x")
    s.connect("load.v", "cyl.v")
    return s


def test_a_law_is_cited_only_when_the_system_uses_it() -> None:
    # The cylinder's docstring names both bulk-modulus laws; only the chosen one's source is cited.
    assert "LeeLee1990" in _cylinder("lee").references()
    assert "LeeLee1990" not in _cylinder("constant").references()
    assert "Eggerth1980" in _cylinder("eggerth").references()


def test_a_model_cites_its_source_and_a_component_its_own() -> None:
    assert "FlightSimulatorND" in hs.load_model("flight-simulator").references()
    from hydroservo.components.reference import citations

    assert citations(c.TwoStageServovalve("sv")) == ["GordicND"]  # the component's model, [GordicND] eqs. (3)-(58)
    assert hs.load_model("position-servo").references()[-1] == "Hopsan2026"  # in the bibliography's order


def test_references_are_keys_of_the_bibliography() -> None:
    from hydroservo.references import keys

    for name in ("flight-simulator", "robot-arm", "servo-solenoid-cylinder"):
        cited = hs.load_model(name).references()
        assert cited and set(cited) <= set(keys())
