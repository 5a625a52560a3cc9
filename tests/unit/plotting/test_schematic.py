"""Circuit diagrams: every component and connection drawn (read from the SVG's elements), readable at 20 components."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.data import example_files
from hydroservo.errors import ParameterError
from hydroservo.plotting.schematic import circuit, draw, drawn, missing

BUILT_IN = ["flight-simulator", "position-servo", "robot-arm", "servo-solenoid-cylinder"]


def _example_models(folder: Path) -> list[Path]:
    files = example_files()
    for name, text in files.items():
        (folder / name).write_text(text, encoding="utf-8")
    return [folder / n for n, t in files.items() if n.endswith(".toml") and "[model]" in t]


@pytest.mark.parametrize("name", BUILT_IN)
def test_every_built_in_model_draws_every_component_and_connection(name: str) -> None:
    system = hs.load_model(name)
    drawing = draw(system)
    assert missing(system, drawing.svg) == []
    components, connections = drawn(drawing.svg)
    assert components == set(system.components)
    assert len(connections) == len(circuit(system).connections)


def test_every_example_model_file_draws(tmp_path: Path) -> None:
    paths = _example_models(tmp_path)
    assert len(paths) >= 4
    for path in paths:
        system = hs.load_model(str(path))
        assert missing(system, draw(system).svg) == [], path.name


def test_the_check_finds_a_component_or_a_connection_left_out() -> None:
    system = hs.load_model("position-servo")
    svg = draw(system).svg
    # remove the relief valve's elements, then the oil line between the valve and the cylinder
    no_relief = re.sub(r'id="component:relief(/\d+)?"', 'id="removed"', svg)
    assert missing(system, no_relief) == ["component relief"]
    link = next(i for i in drawn(svg)[1] if i.startswith("link:") and "cyl.A" in i)
    no_link = re.sub(rf'id="{re.escape(link)}(/\d+)?"', 'id="removed"', svg)
    assert missing(system, no_link) == [f"connection {link}"]


def test_signal_pairs_of_older_model_files_are_one_oil_line() -> None:
    # flight-simulator wires "valve.pA" = "cyl.pB" and "cyl.QB" = "valve.QA": one line from valve A to cylinder B
    found = circuit(hs.load_model("flight-simulator"))
    links = {conn.ends for conn in found.connections if conn.kind == "link"}
    assert ("cyl.B", "valve.A") in links and ("cyl.A", "valve.B") in links and len(links) == 4
    kinds = {conn.ident: conn.kind for conn in found.connections}
    assert kinds["mechanical:cyl--load"] == "mechanical" and kinds["signal:spool--valve"] == "signal"


def _three_loops() -> hs.System:
    """Three position loops (command, controller, spool, valve, cylinder, load) on one pump, relief and tank."""
    s = hs.System("three-axes", t_end=1.0)
    s.set_fluid("iso-vg46", "40 degC")
    for part in (c.Tank("tank"), c.Pump("pump", D="25 cm^3/rev", omega="1500 rpm"),
                 c.ReliefValve("relief", p_crack="160 bar"), c.Accumulator("acc", V0="4 L", p0="90 bar", p_init="140 bar")):
        s.add(part)
    for k in range(3):
        for part in (c.Step(f"command{k}", amplitude=0.5), c.Sum(f"error{k}", gain2=-1.0), c.Gain(f"gain{k}", K=2.0),
                     c.SpoolSecondOrder(f"spool{k}", omega_n="60 Hz", zeta=0.7),
                     c.FourWayValve(f"valve{k}"),
                     c.Cylinder(f"cyl{k}", A_A="20 cm^2", A_B="10 cm^2", x_min="0 m", x_max="0.3 m"),
                     c.Mass(f"load{k}", m="100 kg", incline="0 deg")):
            s.add(part)
    s.connect("pump.P", "relief.A", "acc.P", "valve0.P", "valve1.P", "valve2.P")
    s.connect("tank.P", "pump.S", "relief.B", "valve0.T", "valve1.T", "valve2.T")
    for k in range(3):
        s.connect(f"valve{k}.A", f"cyl{k}.A")
        s.connect(f"valve{k}.B", f"cyl{k}.B")
        s.connect(f"command{k}.y", f"error{k}.u1")
        s.connect(f"load{k}.x", f"error{k}.u2")
        s.connect(f"error{k}.y", f"gain{k}.u")
        s.connect(f"gain{k}.y", f"spool{k}.u")
        s.connect(f"spool{k}.xv", f"valve{k}.xv")
        s.connect(f"cyl{k}.F", f"load{k}.F")
        s.connect(f"load{k}.x", f"cyl{k}.x")
        s.connect(f"load{k}.v", f"cyl{k}.v")
    return s


def test_twenty_five_components_draw_without_a_symbol_on_another() -> None:
    system = _three_loops()
    assert len(system.components) == 25
    drawing = draw(system)
    assert missing(system, drawing.svg) == []
    boxes = list(drawing.boxes.items())
    for i, (a, (ax0, ay0, ax1, ay1)) in enumerate(boxes):  # symbol and label boxes never overlap
        for b, (bx0, by0, bx1, by1) in boxes[i + 1:]:
            overlap = min(ax1, bx1) - max(ax0, bx0) > 1 and min(ay1, by1) - max(ay0, by0) > 1
            assert not overlap, f"{a} and {b} overlap"


def test_a_drawing_saves_as_svg_png_and_pdf_and_refuses_another_format(tmp_path: Path) -> None:
    system = hs.load_model("robot-arm")
    drawing = system.diagram(tmp_path / "arm.svg")
    assert (tmp_path / "arm.svg").read_text(encoding="utf-8").lstrip().startswith("<?xml")
    assert drawing.save(tmp_path / "arm.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert drawing.save(tmp_path / "arm.pdf").read_bytes()[:5] == b"%PDF-"
    with pytest.raises(ParameterError, match=r"arm\.jpg.*expected \.svg, \.png or \.pdf"):
        drawing.save(tmp_path / "arm.jpg")
    assert system._repr_svg_().lstrip().startswith("<?xml")


def test_names_and_parameters_are_shown_in_the_units_given() -> None:
    svg = draw(hs.load_model("flight-simulator")).svg
    assert "A_A = 8.29 in^2" in svg and "p = 1500 psi" in svg and ">valve<" in svg
    assert "A_A =" not in draw(hs.load_model("flight-simulator"), parameters=False).svg
