"""Hopsan's mechanical components mapped to hydroservo's (docs/hopsan.md): the free-length wall, ...

Each mapping with Hopsan's parameter and port names, checked against the closed form of the law it stands for."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from hydroservo.errors import ModelFileError
from hydroservo.io.hopsan_library import import_hopsan


def _hmf(components: list, connections: list, stop: float = 1.0) -> str:
    """A Hopsan model file of ``components`` ((type, name, {parameter: (value, unit)})) and ``connections``."""
    objects = "".join(
        f'<component subtypename="" name="{name}" typename="{kind}" cqstype="S"><parameters>'
        + "".join(f'<parameter type="double" name="{k}" value="{v}" unit="{u}"/>' for k, (v, u) in params.items())
        + "</parameters></component>"
        for kind, name, params in components
    )
    links = "".join(
        f'<connect startcomponent="{a.split(".")[0]}" startport="{a.split(".")[1]}" '
        f'endcomponent="{b.split(".")[0]}" endport="{b.split(".")[1]}"/>'
        for a, b in connections
    )
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n<hopsanmodelfile hmfversion="0.4">'
        '<system subtypename="" name="Mechanics" typename="Subsystem">'
        f'<simulationtime stop="{stop}" timestep="1e-05" start="0" inherit_timestep="true"/>'
        f"<objects>{objects}</objects><connections>{links}</connections></system></hopsanmodelfile>"
    )


def _write(tmp_path: Path, components: list, connections: list, stop: float = 1.0) -> Path:
    path = tmp_path / "model.hmf"
    path.write_text(_hmf(components, connections, stop), encoding="utf-8")
    return path


def test_hopsans_free_length_wall_lets_a_ball_fall_onto_its_spring_and_bounce(tmp_path: Path) -> None:
    """MechanicFreeLengthWall (B, stop_pos, the start position of Pm1) as a Wall: Bouncing Ball in small. A mass
    pushed by 10 N at P1 falls freely with its spring, whose free end starts 0.05 m above the wall: it meets it
    after √(2h/g), is held there while the spring is compressed, and lets go with the impact speed reversed."""
    h, k = 0.05, 1e4
    components = [
        ("MechanicFreeLengthWall", "Wall", {"B#Value": ("0", "Ns/m"), "m_e": ("1", "kg"), "stop_pos": ("0", "m")}),
        ("MechanicTranslationalMass", "Mass", {"m": ("1", "kg"), "B#Value": ("0", "Ns/m"), "k#Value": ("0", "N/m")}),
        ("MechanicForceTransformer", "F", {"F#Value": ("10", "N"), "P1#Position": ("1", "m")}),
        ("MechanicTranslationalSpring", "K", {"k#Value": (str(k), "N/m"), "P1#Position": (str(h), "m"),
                                              "P2#Position": ("0", "m")}),
    ]
    connections = [("K.P1", "Wall.Pm1"), ("Mass.P2", "K.P2"), ("F.P1", "Mass.P1")]
    imp = import_hopsan(_write(tmp_path, components, connections))
    wall = imp.system["Wall"]
    assert (wall.values["B"], wall.values["x_stop"], wall.values["x0"]) == (0.0, 0.0, h)
    t1, v1, w = math.sqrt(2 * h / 10.0), math.sqrt(2 * 10.0 * h), math.sqrt(k)
    t2 = t1 + (math.pi + 2 * math.atan(10.0 / (w * v1))) / w  # when the spring lets go
    r = imp.system.simulate(t_eval=[0.0, 0.5 * t1, t1 + 0.005, t2 + 0.01], accuracy=1e-8, method="cvodes")
    assert r["Wall.Pm1.Position"][1] == pytest.approx(h - 0.5 * 10.0 * (0.5 * t1) ** 2, rel=1e-6)  # falls with the mass
    assert r["Wall.Pm1.Velocity"][1] == pytest.approx(-10.0 * 0.5 * t1, rel=1e-4)
    assert r["Wall.Pm1.Force"][1] == pytest.approx(0.0, abs=1e-9)  # free: Hopsan writes 0
    assert r["Wall.Pm1.Position"][2] == pytest.approx(0.0, abs=1e-9)  # held at the stop
    assert r["Wall.Pm1.Force"][2] == pytest.approx(k * (r["Mass.P2.Position"][2] - h), rel=1e-6)  # compressed
    assert r["Mass.P2.Velocity"][3] == pytest.approx(-v1 + 10.0 * 0.01, rel=1e-5)  # bounced back elastically


def test_a_free_length_wall_starting_below_its_stop_starts_at_it_and_a_negative_damping_is_refused(
    tmp_path: Path,
) -> None:
    components = [
        ("MechanicFreeLengthWall", "Wall", {"B#Value": ("0.5", "Ns/m"), "stop_pos": ("0.2", "m")}),
        ("MechanicTranslationalSpring", "K", {"k#Value": ("100", "N/m"), "P1#Position": ("0.1", "m")}),
        ("MechanicFixedPosition", "G", {}),
    ]
    connections = [("K.P1", "Wall.Pm1"), ("K.P2", "G.Pm1")]
    imp = import_hopsan(_write(tmp_path, components, connections))
    assert imp.system["Wall"].values["x0"] == 0.2 and imp.system["Wall"].values["B"] == 0.5
    components[0][2]["B#Value"] = ("-1", "Ns/m")
    with pytest.raises(ModelFileError, match=r"Wall \(MechanicFreeLengthWall\): B = -1 Ns/m"):
        import_hopsan(_write(tmp_path, components, connections))
