"""Hydraulic ports: a port connected to a port once, nodes that sum any number of flows, clear refusals."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.components.base import REGISTRY
from hydroservo.errors import ModelError
from hydroservo.io.model_file import model_to_toml, system_from_dict
from hydroservo.units import same_dimension


def _parts(s: System) -> None:
    s.add(c.ConstantPressure("supply", p="100 bar"))
    s.add(c.Tank("tank"))
    s.add(c.FourWayValve("valve"))
    s.add(c.Cylinder("cyl", k_stop=1e8, c_stop=1e5))
    s.add(c.Mass("load", m=50.0, incline=0.0))
    s.add(c.Sine("cmd", unit="m", amplitude="0.2 mm", frequency="5 Hz"))
    s.connect("cmd.y", "valve.xv")
    s.connect("cyl.F", "load.F")
    s.connect("load.x", "cyl.x")
    s.connect("load.v", "cyl.v")


def by_ports() -> System:
    s = System("ports", t_end=0.3)
    _parts(s)
    s.connect("supply.P", "valve.P")
    s.connect("valve.T", "tank.P")
    s.connect("valve.A", "cyl.A")
    s.connect("cyl.B", "valve.B")  # order does not matter
    return s


def by_signals() -> System:
    s = System("signals", t_end=0.3)
    _parts(s)
    s.connect("supply.p", "valve.pS")
    s.connect("tank.p", "valve.pT")
    s.connect("cyl.pA", "valve.pA")
    s.connect("cyl.pB", "valve.pB")
    s.connect("valve.QA", "cyl.QA")
    s.connect("valve.QB", "cyl.QB")
    return s


def test_one_connection_per_link_gives_the_same_model_as_two_signals_per_link():
    a, b = by_ports().simulate(), by_signals().simulate()
    assert np.ptp(a["load.x"]) > 1e-3  # the piston really moves
    np.testing.assert_array_equal(a["load.x"], b["load.x"])
    np.testing.assert_array_equal(a["cyl.pA"], b["cyl.pA"])


@pytest.mark.filterwarnings("ignore::hydroservo.errors.ImplausibleResultWarning")  # a charged volume, no supply
def test_a_node_sums_any_number_of_flows_with_their_signs():
    # five valves fed from one volume by one node: the volume loses the sum of their supply flows
    s = System("manifold", t_end=0.01)
    s.add(c.Volume("v", V="1 L", p0="100 bar"))
    s.add(c.Tank("tank"))
    valves = []
    for i in range(5):
        valve = s.add(c.FourWayValve(f"valve{i}", c_v=1e-6 * (i + 1)))
        valves.append(f"{valve.name}.P")
        s.add(c.Step(f"cmd{i}", unit="m", amplitude="0.5 mm"))
        s.connect(f"cmd{i}.y", f"valve{i}.xv")
    s.connect("v.P", *valves)
    for i in range(5):
        s.add(c.Volume(f"a{i}", V="0.1 L"))
        s.add(c.Volume(f"b{i}", V="0.1 L", p0="50 bar"))
        s.connect(f"valve{i}.A", f"a{i}.P")
        s.connect(f"valve{i}.B", f"b{i}.P")
        s.connect(f"valve{i}.T", "tank.P")
    r = s.simulate(n_points=2001, rtol=1e-9, atol=1e-3)
    dt = np.diff(r.t)
    # the volume's pressure rate is -beta/V times the sum of the valves' supply flows, at every step
    qs = sum(r[f"valve{i}.QS"] for i in range(5))
    dp = np.diff(r["v.p"])
    expected = -1.4e9 / 1e-3 * 0.5 * (qs[1:] + qs[:-1]) * dt
    np.testing.assert_allclose(dp, expected, rtol=2e-2, atol=1.0)
    assert len(s.nodes()) == 1 + 1 + 10  # supply manifold, the tank node, ten use ports


def test_links_sharing_a_port_join_one_node():
    s = by_ports()
    s.add(c.Volume("extra", V="0.1 L"))
    with pytest.raises(ModelError, match="supply.P – valve.P – extra.P: supply.P, extra.P each set the node's pressure"):
        s.connect("valve.P", "extra.P")
        s.build()


def test_a_node_without_a_pressure_port_asks_for_a_volume():
    s = System("two valves")
    s.add(c.FourWayValve("v1"))
    s.add(c.FourWayValve("v2"))
    s.add(c.Step("cmd", unit="m", amplitude="1 mm"))
    s.connect("cmd.y", "v1.xv", "v2.xv")
    s.connect("v1.A", "v2.P")
    with pytest.raises(ModelError, match=r"v1.A – v2.P: every port there takes a pressure.*connect a Volume there"):
        s.build()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("valve.A", "cyl.C"), "Cylinder 'cyl' has no port 'C'; its ports: A, B, R"),
        (("valve.A", "cyl.pA"), "has no port 'pA'"),
        (("valve.A", "valve.A"), "a port is named twice"),
        (("valve.A",), "connects to at least one other port"),
    ],
)
def test_bad_hydraulic_connections_are_refused_with_the_ports_named(args, message):
    s = System("s")
    _parts(s)
    with pytest.raises(ModelError, match=message):
        s.connect(*args)


def test_a_port_and_its_own_signals_cannot_both_be_connected():
    s = by_signals()
    with pytest.raises(ModelError, match="valve.A's pA is already connected as a signal to 'cyl.pA'"):
        s.connect("valve.A", "cyl.A")
    s = by_ports()
    s.add(c.ConstantPressure("other"))
    with pytest.raises(ModelError, match="already fed by the node of port valve.A"):
        s.connect("other.p", "valve.pA")


def test_model_files_write_one_line_per_node_and_read_back_to_the_same_results():
    import tomllib

    s = by_ports()
    text = model_to_toml(s)
    assert '"valve.A" = "cyl.A"' in text and '"cyl.B" = "valve.B"' in text
    back = system_from_dict(tomllib.loads(text))
    assert back.nodes() == s.nodes()
    np.testing.assert_array_equal(back.simulate()["load.x"], s.simulate()["load.x"])


def test_a_list_in_a_model_file_makes_a_node_of_many_ports():
    import tomllib

    text = model_to_toml(by_ports()).replace('"supply.P" = "valve.P"', '"supply.P" = ["valve.P"]')
    assert tomllib.loads(text)["connections"]["supply.P"] == ["valve.P"]
    assert system_from_dict(tomllib.loads(text)).nodes() == by_ports().nodes()


@pytest.mark.parametrize("cls", sorted(REGISTRY.types.values(), key=lambda k: k.__name__), ids=lambda k: k.__name__)
def test_every_declared_hydraulic_port_pairs_a_pressure_and_a_flow_of_opposite_causality(cls):
    for name, port in cls.HYDRAULIC.items():
        flow_port = port.p in cls.INPUTS and port.Q in cls.OUTPUTS
        pressure_port = port.p in cls.OUTPUTS and port.Q in cls.INPUTS
        assert flow_port != pressure_port, f"{cls.__name__}.{name}: expected p in, Q out, or p out, Q in"
        p_unit = (cls.INPUTS.get(port.p) or cls.OUTPUTS[port.p]).unit
        q_unit = (cls.INPUTS.get(port.Q) or cls.OUTPUTS[port.Q]).unit
        assert same_dimension(p_unit, "Pa") and same_dimension(q_unit, "m^3/s"), (cls.__name__, name)


# -- mechanical nodes ---------------------------------------------------------------------------------------------


def _oscillator(force: float = 0.0) -> System:
    from hydroservo.components import Constant, FixedPosition, ForceSource, Mass, Spring

    s = System("oscillator")
    s.add(Mass("m", m=2.0, B=0.0, x0=0.01))
    s.add(Spring("k", k_spring=800.0))
    s.add(FixedPosition("ground"))
    s.add(ForceSource("f"))
    s.add(Constant("F0", unit="N", value=force))
    s.connect("m.P2", "k.P1")
    s.connect("k.P2", "ground.P")
    s.connect("f.P", "m.P1")
    s.connect("F0.y", "f.u")
    return s


def test_mass_on_a_spring_joined_port_to_port_oscillates_as_it_should() -> None:
    """x(t) = x0 cos(ω t), ω = √(k/m) = 20 rad/s: the spring's force reaches the mass through two ports of
    opposite directions (the mass's end 2 outward along +x, the spring's end 1 outward along -x)."""
    t = np.linspace(0.0, 1.0, 201)
    r = _oscillator().simulate(t_eval=t, accuracy=1e-8)
    assert np.max(np.abs(r.get("m.x") - 0.01 * np.cos(20.0 * t))) < 1e-6
    assert np.allclose(r.get("k.F"), -800.0 * r.get("m.x"), atol=1e-9)  # +x compresses the spring: tension < 0


def test_force_source_at_end_1_pushes_the_mass_along_plus_x() -> None:
    """A force pushing outward from the source at the mass's end 1 drives +x: static deflection F/k."""
    s = _oscillator(force=100.0)
    s["m"].set(B=200.0, x0=0.0)
    r = s.simulate(t_end=3.0)
    assert r.get("m.x")[-1] == pytest.approx(100.0 / 800.0, rel=1e-5)
    assert r.get("k.F")[-1] == pytest.approx(-100.0, rel=1e-5)  # compressed: negative tension


def test_mechanical_nodes_need_one_motion_port() -> None:
    from hydroservo.components import FixedPosition, ForceSource, Mass, Spring

    s = System("no motion")
    s.add(Spring("k"))
    s.add(ForceSource("f"))
    s.add(FixedPosition("g"))
    s.connect("k.P1", "f.P")
    s.connect("k.P2", "g.P")
    with pytest.raises(ModelError, match=r"mechanical node k\.P1 – f\.P: every port there takes a motion"):
        s.hydraulic_inputs()
    s = System("two motions")
    s.add(Mass("m"))
    s.add(FixedPosition("g"))
    s.connect("m.P1", "g.P")
    with pytest.raises(ModelError, match=r"m\.P1, g\.P each set the node's motion"):
        s.hydraulic_inputs()


def test_ports_of_different_kinds_do_not_join() -> None:
    from hydroservo.components import Mass, Volume

    s = System("mixed")
    s.add(Mass("m"))
    s.add(Volume("v"))
    with pytest.raises(ModelError, match=r"ports of different kinds cannot join"):
        s.connect("m.P1", "v.P")
    s2 = System("both")
    s2.add(Mass("m"))
    from hydroservo.components import Cylinder

    s2.add(Cylinder("c"))
    s2.connect("c.F", "m.F_P1")
    with pytest.raises(ModelError, match=r"already connected as a signal"):
        s2.connect("c.R", "m.P1")
