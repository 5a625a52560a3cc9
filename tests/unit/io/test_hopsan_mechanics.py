"""Hopsan's mechanical components mapped to hydroservo's (docs/hopsan.md): the free-length wall, ...

Each mapping with Hopsan's parameter and port names, checked against the closed form of the law it stands for."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
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


@pytest.mark.parametrize("typename", ["MechanicRotationalInertiaWithCoulombFriction",
                                      "MechanicRotationalInertiaWithCoulumbFriction"])
def test_hopsans_rotational_inertia_with_coulomb_friction_under_either_name(tmp_path: Path, typename: str) -> None:
    """MechanicRotationalInertiaWithCoulombFriction (and the older files' ...Coulumb..., which Hopsan's GUI renames):
    J, B, t_s, t_k as RotationalInertia's J, B_rot, T_c0 + T_s0 and T_c0; a static friction below the kinetic one
    acts as the kinetic one (T_s0 0). Twisted at P1 by 30 N m, below t_k = 50 N m, it stays; by 80 N m it turns
    against t_k and B: ω = (80 - 50)/B (1 - exp(-B t/J))."""
    components = [
        (typename, "Stuck", {"J#Value": ("0.5", "kgm^2"), "B#Value": ("3", "Nms/rad"), "t_s": ("10", "Nm"),
                             "t_k": ("50", "Nm")}),
        (typename, "Turns", {"J#Value": ("0.5", "kgm^2"), "B#Value": ("3", "Nms/rad"), "t_s": ("10", "Nm"),
                             "t_k": ("50", "Nm")}),
        ("MechanicTorqueTransformer", "T30", {"T#Value": ("30", "Nm")}),
        ("MechanicTorqueTransformer", "T80", {"T#Value": ("80", "Nm")}),
    ]
    connections = [("T30.P1", "Stuck.P1"), ("T80.P1", "Turns.P1")]
    imp = import_hopsan(_write(tmp_path, components, connections))
    j = imp.system["Turns"]
    assert (j.values["J"], j.values["B_rot"], j.values["T_c0"], j.values["T_s0"]) == (0.5, 3.0, 50.0, 0.0)
    t = np.array([0.0, 0.1, 0.5])
    r = imp.system.simulate(t_eval=t, accuracy=1e-8, method="cvodes")
    assert np.max(np.abs(r["Stuck.P1.AngularVelocity"])) < 1e-4
    np.testing.assert_allclose(-r["Turns.P1.AngularVelocity"], 10.0 * (1.0 - np.exp(-6.0 * t)), atol=2e-3)


def test_hopsans_motor_is_a_torque_source_under_pid_speed_control(tmp_path: Path) -> None:
    """MechanicMotor: the torque K_p e + K_i ∫e + K_d ė on its speed error e = omega_ref - ω. On an inertia J
    (no damping, no friction) with K_p alone, ω = omega_ref (1 - exp(-K_p t/J)); with K_d alone, the error's
    step at the start is an impulse K_d omega_ref that sets the inertia at once to K_d omega_ref/(J + K_d), which
    then stays (J ω' = -K_d ω')."""
    def model(kp: str, kd: str) -> Path:
        components = [
            ("MechanicMotor", "Motor", {"omega_ref": ("20", ""), "K_p": (kp, ""), "K_i": ("0", ""), "K_d": (kd, "")}),
            ("MechanicRotationalInertia", "J", {"J": ("0.5", "kgm^2"), "B#Value": ("0", "Nms/rad"),
                                                "k#Value": ("0", "Nm/rad")}),
            ("MechanicTorqueTransformer", "T", {"T#Value": ("0", "Nm")}),
        ]
        return _write(tmp_path, components, [("Motor.P1", "J.P1"), ("J.P2", "T.P1")])

    t = np.array([0.0, 0.05, 0.2])
    imp = import_hopsan(model("10", "0"))
    assert imp.system["Motor_pid"].values["Kp"] == 10.0
    r = imp.system.simulate(t_eval=t, accuracy=1e-8, method="cvodes")
    np.testing.assert_allclose(r["J.P2.AngularVelocity"], 20.0 * (1.0 - np.exp(-20.0 * t)), atol=1e-4)
    np.testing.assert_allclose(r["Motor.P1.AngularVelocity"], -r["J.P2.AngularVelocity"])  # Hopsan's node: the Q's
    r = import_hopsan(model("0", "0.5")).system.simulate(t_eval=t, accuracy=1e-8, method="cvodes")
    np.testing.assert_allclose(r["J.P2.AngularVelocity"][1:], 10.0, rtol=1e-4)


def test_hopsans_mkc_load_is_a_mass_with_dry_friction_a_spring_and_a_stroke(tmp_path: Path) -> None:
    """MechanicMkcload1D (mL, bL, kL, fc, xmin, xmax) as a Mass with B, k_spring, F_c0 and stiff stops; its output
    fs is kL x. Pushed at Pm1 by 30 N against fc = 50 N it stays at its start; by 150 N it slides against fc and
    bL: mL ẍ = 150 - 50 - bL ẋ - kL x, overdamped, which creeps up to x = 100/kL within its stroke (where the
    friction would hold it anywhere up to 200/kL)."""
    components = [
        ("MechanicMkcload1D", "Load", {"mL#Value": ("1", "kg"), "bL#Value": ("200", "Ns/m"), "kL#Value": ("1000", "N/m"),
                                       "fc#Value": ("50", "N"), "xmin#Value": ("0", "m"), "xmax#Value": ("1", "m")}),
        ("MechanicMkcload1D", "Held", {"mL#Value": ("1", "kg"), "bL#Value": ("20", "Ns/m"), "kL#Value": ("0", "N/m"),
                                       "fc#Value": ("50", "N"), "xmin#Value": ("0", "m"), "xmax#Value": ("1", "m")}),
        ("MechanicForceTransformer", "F150", {"F#Value": ("150", "N")}),
        ("MechanicForceTransformer", "F30", {"F#Value": ("30", "N")}),
        ("MechanicForceTransformer", "F0", {"F#Value": ("0", "N")}),
        ("MechanicForceTransformer", "G0", {"F#Value": ("0", "N")}),
    ]
    connections = [("F150.P1", "Load.Pm1"), ("F0.P1", "Load.Pm2"), ("F30.P1", "Held.Pm1"), ("G0.P1", "Held.Pm2")]
    imp = import_hopsan(_write(tmp_path, components, connections))
    load = imp.system["Load"]
    assert (load.values["B"], load.values["k_spring"], load.values["F_c0"], load.values["F_s0"]) == (200.0, 1e3, 50.0, 0.0)
    r = imp.system.simulate(t_end=3.0, accuracy=1e-8, method="cvodes")
    assert r["Load.Pm2.Position"][-1] == pytest.approx(0.1, rel=1e-3)
    assert r["Load.fs.Value"][-1] == pytest.approx(100.0, rel=1e-3)
    assert abs(r["Held.Pm2.Position"][-1]) < 1e-4


def test_hopsans_m2_load_is_a_mass_pair_starting_where_it_writes_its_ends(tmp_path: Path) -> None:
    """MechanicM2load1D (m1, m2, fc, xpmin, xpmax; its outputs xt, vt) as a MassPair. It writes its ends' start
    positions from xt (0.1 m here) whatever its neighbours declare, so a spring joined at Pm1, relaxed at its
    start as Hopsan's, is relaxed there: pushed by nothing, the pair stays. Pushed apart at Pm3 by 60 N against
    fc = 10 N, the masses (20 and 30 kg, μ = 12 kg) part at 50/12 m/s² until the stroke's end, 0.5 m."""
    pair = {"m1#Value": ("20", "kg"), "m2#Value": ("30", "kg"), "fc#Value": ("10", "N"), "xpmin#Value": ("0", "m"),
            "xpmax#Value": ("0.5", "m"), "xt#Value": ("0.1", "")}
    components = [
        ("MechanicM2load1D", "Pair", pair),
        ("MechanicTranslationalSpring", "K", {"k#Value": ("1e6", "N/m")}),
        ("MechanicFixedPosition", "G", {}),
        ("MechanicForceTransformer", "F2", {"F#Value": ("0", "N")}),
        ("MechanicForceTransformer", "F3", {"F#Value": ("0", "N")}),
    ]
    connections = [("G.Pm1", "K.P1"), ("K.P2", "Pair.Pm1"), ("F2.P1", "Pair.Pm2"), ("F3.P1", "Pair.Pm3")]
    imp = import_hopsan(_write(tmp_path, components, connections))
    values = imp.system["Pair"].values
    assert (values["m1"], values["F_c0"], values["x_p_max"], values["xt0"]) == (20.0, 10.0, 0.5, 0.1)
    r = imp.system.simulate(t_eval=[0.0, 0.5], accuracy=1e-8, method="cvodes")
    assert r["Pair.Pm1.Position"][0] == pytest.approx(-0.1) and r["Pair.Pm2.Position"][0] == pytest.approx(0.1)
    np.testing.assert_allclose(r["K.P2.Force"], 0.0, atol=1e-6)  # relaxed where the pair starts
    np.testing.assert_allclose(r["Pair.xt.Value"], 0.1)
    components[1:3] = [("MechanicForceTransformer", "F1", {"F#Value": ("0", "N")})]
    components[-1] = ("MechanicForceTransformer", "F3", {"F#Value": ("60", "N")})
    connections[:2] = [("F1.P1", "Pair.Pm1")]
    r = import_hopsan(_write(tmp_path, components, connections)).system.simulate(t_eval=[0.0, 0.2, 1.0])
    assert r["Pair.Pm3.Position"][1] == pytest.approx(-50.0 / 12.0 * 0.2**2 / 2, rel=1e-3)  # the stroke is -x3
    assert r["Pair.Pm3.Position"][2] == pytest.approx(-0.5, abs=1e-5)


def test_hopsans_geared_inertia_and_mass_on_a_lever_move_their_first_ends_by_the_ratio(tmp_path: Path) -> None:
    """MechanicRotationalInertiaWithGearRatio (J, B, gear ratio omega) as a RotationalInertia with n_gear: a torque
    of 4 N m at P1 through omega = 2 turns it as J ω' = 2·4 - B ω, ω = 4 (1 - exp(-4 t)) for J 0.5, B 2, and P1 at
    -2 ω. MechanicTranslationalMassWithLever (m, B, L_1, L_2) as a Mass with n_lever = L_1/(L_1 + L_2): 10 N at
    P1 through arms of 1 and 3 m moves it as m ẍ = 10/4 - B ẋ, v = 0.5 (1 - exp(-5 t)) for m 1, B 5, and P1 at
    -v/4."""
    components = [
        ("MechanicRotationalInertiaWithGearRatio", "J", {"J": ("0.5", "kgm^2"), "B#Value": ("2", "Nms/rad"),
                                                         "omega#Value": ("2", "")}),
        ("MechanicTorqueTransformer", "T", {"T#Value": ("4", "Nm")}),
        ("MechanicTorqueTransformer", "T0", {"T#Value": ("0", "Nm")}),
        ("MechanicTranslationalMassWithLever", "M", {"m#Value": ("1", "kg"), "B#Value": ("5", "Ns/m"),
                                                     "L_1": ("1", "m"), "L_2": ("3", "m")}),
        ("MechanicForceTransformer", "F", {"F#Value": ("10", "N")}),
        ("MechanicForceTransformer", "F0", {"F#Value": ("0", "N")}),
    ]
    connections = [("T.P1", "J.P1"), ("T0.P1", "J.P2"), ("F.P1", "M.P1"), ("F0.P1", "M.P2")]
    imp = import_hopsan(_write(tmp_path, components, connections))
    assert imp.system["J"].values["n_gear"] == 2.0 and imp.system["M"].values["n_lever"] == 0.25
    t = np.array([0.0, 0.1, 0.5, 1.0])
    r = imp.system.simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    omega = 4.0 * (1.0 - np.exp(-4.0 * t))
    np.testing.assert_allclose(r["J.P2.AngularVelocity"], omega, atol=1e-6)
    np.testing.assert_allclose(r["J.P1.AngularVelocity"], -2.0 * omega, atol=1e-6)
    v = 0.5 * (1.0 - np.exp(-5.0 * t))
    np.testing.assert_allclose(r["M.P2.Velocity"], v, atol=1e-6)
    np.testing.assert_allclose(r["M.P1.Velocity"], -v / 4.0, atol=1e-6)
    components[0][2]["omega#Value"] = ("0", "")
    with pytest.raises(ModelFileError, match="gear ratio omega = 0"):
        import_hopsan(_write(tmp_path, components, connections))


def test_hopsans_vehicle_is_driven_by_the_torque_pressing_on_its_wheels(tmp_path: Path) -> None:
    """MechanicVehicle1D (Mc, cfr, CdA, rwheel, rho; outputs vc, xc, fd, fr) as a Vehicle with Hopsan's g of
    9.82 m/s²: 300 N m on wheels of 1 m drives 1000 kg against fr = 0.02·9.82·1000 N, v̇c = (300 - 196.4)/1000 m/s²
    without drag; both ports turn at -vc/rwheel, as Hopsan writes them."""
    components = [
        ("MechanicVehicle1D", "Car", {"Mc#Value": ("1000", "kg"), "cfr#Value": ("0.02", "N/N"), "CdA#Value": ("0", "m2"),
                                      "rwheel#Value": ("1", "m"), "rho#Value": ("1.25", "kg/m3")}),
        ("MechanicTorqueTransformer", "T", {"T#Value": ("300", "Nm")}),
        ("MechanicTorqueTransformer", "T0", {"T#Value": ("0", "Nm")}),
    ]
    imp = import_hopsan(_write(tmp_path, components, [("T.P1", "Car.Pmr1"), ("T0.P1", "Car.Pmr2")]))
    car = imp.system["Car"]
    assert (car.values["M"], car.values["c_r"], car.values["g"], car.values["r_wheel"]) == (1000.0, 0.02, 9.82, 1.0)
    t = np.array([0.0, 1.0, 2.0])
    r = imp.system.simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    a = (300.0 - 0.02 * 9.82 * 1000.0) / 1000.0
    # within about v_reg (1e-5 m/s), over which the rolling resistance sets in as the vehicle starts
    np.testing.assert_allclose(r["Car.vc.Value"], a * t, atol=2e-5)
    np.testing.assert_allclose(r["Car.Pmr2.AngularVelocity"], -a * t, atol=2e-5)
    assert r["Car.fr.Value"][-1] == pytest.approx(196.4)


def test_hopsans_j_links_are_cranks_whose_link_end_starts_where_they_write_it(tmp_path: Path) -> None:
    """MechanicJLink (JL, BL, link, x0, thetamin, thetamax) and MechanicJLink2 (a second translational port Pm0) as
    Cranks with stiff stops; their link's end starts at x0 - link sin θ, where a spring joined there, declared at
    -0.1 m, is relaxed, as Hopsan's (which integrates velocities): untouched, it stays unloaded."""
    components = [
        ("MechanicJLink", "L1", {"JL#Value": ("1", "kgm2"), "BL#Value": ("1", "Ns/rad"), "link#Value": ("0.1", ""),
                                 "x0#Value": ("0", ""), "thetamin#Value": ("-1.2", "rad"), "thetamax#Value": ("1.2", "rad")}),
        ("MechanicJLink2", "L2", {"JL#Value": ("1", "kgm2"), "BL#Value": ("1", "Ns/rad"), "link#Value": ("0.1", ""),
                                  "x0#Value": ("0.1", "")}),
        ("MechanicTranslationalSpring", "K", {"k#Value": ("1e5", "N/m"), "P2#Position": ("-0.1", "m")}),
        ("MechanicFixedPosition", "G", {}),
        ("MechanicTorqueTransformer", "T1", {"T#Value": ("0", "Nm")}),
        ("MechanicTorqueTransformer", "T2", {"T#Value": ("0", "Nm")}),
        ("MechanicForceTransformer", "F0", {"F#Value": ("0", "N")}),
        ("MechanicForceTransformer", "F1", {"F#Value": ("0", "N")}),
    ]
    connections = [("G.Pm1", "K.P1"), ("K.P2", "L1.Pm1"), ("T1.P1", "L1.Pmr2"), ("T2.P1", "L2.Pmr2"),
                   ("F0.P1", "L2.Pm0"), ("F1.P1", "L2.Pm1")]
    imp = import_hopsan(_write(tmp_path, components, connections))
    link = imp.system["L1"].values
    assert (link["J"], link["r_link"], link["x_link"], link["theta_min"], link["theta_max"]) == (1.0, 0.1, 0.0, -1.2, 1.2)
    r = imp.system.simulate(t_eval=[0.0, 0.5], accuracy=1e-8, method="cvodes")
    np.testing.assert_allclose(r["K.P2.Force"], 0.0, atol=1e-6)
    np.testing.assert_allclose(r["L2.Pm0.Position"], 0.1)
    np.testing.assert_allclose(r["L2.Pm1.Position"], 0.1)
