"""Hopsan's axial piston machine parts imported (docs/hopsan.md): MechanicCylinderBlockWithSwashPlate,
HydraulicPumpPiston and HydraulicValvePlate, with Hopsan's parameter and port names, each multiport connection a
piston in the order Hopsan connects them, checked against the closed forms of their laws."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from hydroservo.errors import ModelFileError
from hydroservo.io.hopsan_library import import_hopsan
from hydroservo.io.model_file import model_to_toml, system_from_dict

P_ATM = 101325.0


def _hmf(components: list, connections: list) -> str:
    """A Hopsan model file of ``components`` ((type, name, {parameter: value})) and ``connections``, in order."""
    objects = "".join(
        f'<component subtypename="" name="{name}" typename="{kind}" cqstype="S"><parameters>'
        + "".join(f'<parameter type="double" name="{k}" value="{v}" unit=""/>' for k, v in params.items())
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
        '<system subtypename="" name="Pump" typename="Subsystem">'
        '<simulationtime stop="0.05" timestep="1e-05" start="0" inherit_timestep="true"/>'
        f"<objects>{objects}</objects><connections>{links}</connections></system></hopsanmodelfile>"
    )


PISTON = {"A_1#Value": "2.5e-4", "s_l#Value": "0.1", "V_1#Value": "2.5e-6", "B_p#Value": "3",
          "Beta_e#Value": "1e9", "c_leak#Value": "1e-13", "F_0#Value": "2500", "P1#Pressure": "1e5"}
PLATE = {"phi_P#Value": "127.7", "phi_1#Value": "20.3", "phi_2#Value": "19.8", "Delta_alpha#Value": "7.8533",
         "alpha_f#Value": "30.3", "R_f#Value": "0.029", "theta_1#Value": "6", "theta_2#Value": "90",
         "rho#Value": "876"}


def _pump(angle: float, torque: float = 30.0, extra: list | None = None, links: list | None = None) -> tuple[list, list]:
    components = [
        ("MechanicCylinderBlockWithSwashPlate", "Block", {"B#Value": "0.5", "r#Value": "0.04", "J": "0.01",
                                                          "theta_offset#Value": "4", "angle#Value": repr(angle),
                                                          "m_p": "0.3", "r_p": "0.009"}),
        *[("HydraulicPumpPiston", name, PISTON) for name in ("Pa", "Pb", "Pc")],
        ("HydraulicValvePlate", "VP", PLATE),
        ("HydraulicPressureSourceC", "Low", {"p#Value": "2e6"}),
        ("HydraulicPressureSourceC", "High", {"p#Value": "4e6"}),
        ("MechanicTorqueTransformer", "T", {"T#Value": repr(-torque)}),
        ("MechanicAngularVelocitySensor", "W", {}),
        *(extra or []),
    ]
    connections = [
        ("Pa.P3", "Block.P1"), ("Pb.P3", "Block.P1"), ("Pc.P3", "Block.P1"),  # the block's C1, C2, C3
        ("Pc.P1", "VP.P1"), ("Pb.P1", "VP.P1"), ("Pa.P1", "VP.P1"),  # the plate's C1 is Pc's bore, C3 Pa's
        ("VP.PA", "Low.P1"), ("VP.PB", "High.P1"), ("Block.P2", "T.P1"), ("W.P1", "Block.P2"),
        ("W.out", "VP.movement"), *(links or []),
    ]
    return components, connections


def _write(tmp_path: Path, components: list, connections: list) -> Path:
    path = tmp_path / "pump.hmf"
    path.write_text(_hmf(components, connections), encoding="utf-8")
    return path


def test_hopsans_swash_plate_block_turns_with_its_torque_where_its_plate_is_not_tilted(tmp_path: Path) -> None:
    """With the swash plate at angle 0 the pistons stand still at 0 (Hopsan's block writes 0 to their positions)
    and turn nothing: J ω' = -T - B ω, ω = -T/B (1 - e^(-B t/J)) with J alone (Hopsan adds the pistons' m_p to J
    after its filters took it); the valve plate's angle (DEBUG1), the integral of the block's speed from the
    sensor, is the block's; each piston presses its foot out with A_1 p + F_0 on its absolute pressure."""
    imp = import_hopsan(_write(tmp_path, *_pump(0.0)))
    block, plate = imp.system["Block"], imp.system["VP"]
    assert block.pistons == 3 and plate.pistons == 3 and block.values["J"] == 0.01 and block.values["x0"] == 0.0
    assert plate.values["phi_P"] == pytest.approx(math.radians(127.7)) and plate.values["Cd"] == 0.67
    assert imp.system["Pa"].values["p_case"] == pytest.approx(-P_ATM)
    t = np.linspace(0.0, 0.05, 6)
    r = imp.system.simulate(t_eval=t, method="cvodes", accuracy=1e-7)
    omega = 30.0 / 0.5 * (1.0 - np.exp(-0.5 * t / 0.01))
    np.testing.assert_allclose(r["Block.P2.AngularVelocity"], omega, rtol=1e-6)
    np.testing.assert_allclose(r["VP.DEBUG1.Value"], r["Block.P2.Angle"], atol=1e-9)
    for name in ("Pa", "Pb", "Pc"):
        np.testing.assert_allclose(r[f"{name}.P3.Position"], 0.0, atol=1e-15)
        np.testing.assert_allclose(r[f"{name}.P3.Force"][1:], 2.5e-4 * r[f"{name}.P1.Pressure"][1:] + 2500.0,
                                   rtol=1e-9)


@pytest.mark.filterwarnings("ignore::hydroservo.errors.ImplausibleResultWarning")  # bores trapped as it spins up
def test_hopsans_pistons_stroke_with_the_block_and_meet_the_plate_in_the_order_of_its_connections(
    tmp_path: Path,
) -> None:
    """Tilted by 0.2 rad, the k-th piston connected to the block is at r tan γ sin(-θ - offset - 2π k/3) (k from
    0), moving at -r tan γ cos(...) ω; the plate's k-th connection is its k-th bore (here Pc's, Pb's, Pa's),
    whose flow is Hopsan's flow into that piston; the force on each foot is A_1 p + F_0 + B_p v (Hopsan's
    velocity into the bore)."""
    imp = import_hopsan(_write(tmp_path, *_pump(0.2, torque=200.0)))
    r = imp.system.simulate(t_eval=np.linspace(0.0, 0.05, 11), method="cvodes")
    theta, omega = r["Block.P2.Angle"], r["Block.P2.AngularVelocity"]
    stroke = 0.04 * math.tan(0.2)
    assert np.ptp(theta) > 1.0
    for k, name in enumerate(("Pa", "Pb", "Pc")):
        a = -theta - 4.0 - 2.0 * math.pi * k / 3.0
        np.testing.assert_allclose(r[f"{name}.P3.Position"], stroke * np.sin(a), atol=1e-12)
        np.testing.assert_allclose(r[f"{name}.P3.Velocity"], -stroke * np.cos(a) * omega, atol=1e-9)
        force = 2.5e-4 * r[f"{name}.P1.Pressure"] + 2500.0 + 3.0 * r[f"{name}.P3.Velocity"]
        np.testing.assert_allclose(r[f"{name}.P3.Force"][1:], force[1:], rtol=1e-9)
    for bore, name in ((1, "Pc"), (2, "Pb"), (3, "Pa")):
        np.testing.assert_allclose(r[f"{name}.P1.Flow"], r[f"VP.Q{bore}"], rtol=1e-12, atol=1e-15)
    assert np.max(np.abs(r["VP.Q1"])) > 1e-5  # the bores do pass oil
    # the model file keeps the number of pistons and the connections of each
    again = system_from_dict(tomllib.loads(model_to_toml(imp.system)), "round trip")
    assert again["Block"].pistons == 3 and again["VP"].pistons == 3
    r2 = again.simulate(t_eval=np.linspace(0.0, 0.05, 11), method="cvodes")
    np.testing.assert_allclose(r2["Pa.P1.Pressure"], r["Pa.P1.Pressure"], rtol=1e-9)


def test_hopsans_machine_parts_refuse_what_they_cannot_follow(tmp_path: Path) -> None:
    """A swash plate angle driven by a varying signal, and a valve plate with no bore, are refused with the
    component named."""
    ramp = ("SignalRamp", "R", {"y_0#Value": "0", "y_A#Value": "0.2", "t_start#Value": "0", "t_end#Value": "0.01"})
    components, connections = _pump(0.2, extra=[ramp], links=[("R.out", "Block.angle")])
    with pytest.raises(ModelFileError, match=r"Block\.angle driven by a signal is not supported"):
        import_hopsan(_write(tmp_path, components, connections))
    components, connections = _pump(0.2)
    connections = [c for c in connections if c[1] != "VP.P1"]
    with pytest.raises(ModelFileError, match=r"VP \(HydraulicValvePlate\): nothing is connected to its multiport P1"):
        import_hopsan(_write(tmp_path, components, connections))


def test_hopsans_swash_plate_strokes_its_pistons_at_the_speed_it_is_given(tmp_path: Path) -> None:
    """MechanicSwashPlate: its angle the integral of ``movement`` from 0, connection i's foot at r tan(angle)
    sin(a_1 - theta_offset - 2π i/N) moving at r tan(angle) cos(·) movement (its startX 0); the forces on its
    ports are those of what is joined to them (three force sources); its torque output is not mapped, and a
    connection to it is refused."""
    components = [
        ("MechanicSwashPlate", "Plate", {"r#Value": "0.05", "angle#Value": "0.2", "theta_offset#Value": "0.3",
                                         "movement#Value": "10"}),
        *[("MechanicForceTransformer", name, {"F#Value": force}) for name, force in (("Fa", "100"), ("Fb", "-40"),
                                                                                      ("Fc", "70"))],
        ("SignalGain", "Gain", {"k#Value": "1"}),
    ]
    connections = [("Fa.P1", "Plate.P1"), ("Fb.P1", "Plate.P1"), ("Fc.P1", "Plate.P1")]
    system = import_hopsan(_write(tmp_path, components, connections)).system
    assert system["Plate"].pistons == 3 and system["Plate"].values["x0"] == 0.0
    t = np.array([0.0, 0.013, 0.05, 0.3])
    r = system.simulate(t_eval=t, accuracy=1e-9)
    stroke = 0.05 * math.tan(0.2)
    for i, name in enumerate(("Fa", "Fb", "Fc")):
        a = 10.0 * t - 0.3 - 2 * math.pi * i / 3
        np.testing.assert_allclose(r[f"{name}.P1.Position"], stroke * np.sin(a), atol=1e-9)
        np.testing.assert_allclose(r[f"{name}.P1.Velocity"], stroke * np.cos(a) * 10.0, atol=1e-7)
    np.testing.assert_allclose(r["Fb.P1.Force"], -40.0)
    with pytest.raises(ModelFileError, match=r"Plate.*torque"):
        import_hopsan(_write(tmp_path, components, [*connections, ("Plate.torque", "Gain.in")]))
