"""An axial piston machine's parts (Hopsan's MachineParts): the swash plate's strokes, the valve plate's openings,
a pump piston's chamber, against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.errors import ParameterError
from hydroservo.laws.axial_piston import swash_plate_piston, valve_plate_opening

DEG = math.pi / 180.0
#: In-Line Axial Piston Machine's valve plate: phi_P, Delta_alpha, alpha_f, phi_1, phi_2, theta_1, theta_2, R_f
PLATE = (127.7 * DEG, 7.8533 * DEG, 30.3 * DEG, 20.3 * DEG, 19.8 * DEG, 6.0 * DEG, 90.0 * DEG, 0.029)


def _start(theta_from_notch: float, start: float = 0.0) -> float:
    """The block's angle at which a bore has come ``theta_from_notch`` past where its port's first notch begins."""
    phi_p, d_alpha, _, phi_1 = PLATE[:4]
    return theta_from_notch + start + math.pi / 2 - phi_p / 2 - phi_1 - d_alpha


def test_valve_plate_opening_is_the_notch_then_the_full_port_then_closed() -> None:
    """In the first notch (x = R_f θ' from its start, shorter than g_1) the area is x² tan²θ_1 tan(θ_2/2)
    (tan θ_1 < 1, the smaller of Hopsan's two); past notch and rounded end, in the kidney, the bore's full port
    2k_2 + 2r(R - 2r) = 2rR - (4 - π)r²; beyond the second notch none; the same every turn (Hopsan's measure of
    the angle instead: shut before the bore first reaches the notch, a negative angle mirrored). The port B of the same bore is the same half a turn later."""
    phi_p, d_alpha, alpha_f, phi_1, phi_2, theta_1, theta_2, r_f = PLATE
    x = 0.5 * phi_1 * r_f
    notch = valve_plate_opening(_start(0.5 * phi_1), 0.0, *PLATE)
    assert notch == pytest.approx(x * x * math.tan(theta_1) ** 2 * math.tan(theta_2 / 2), rel=1e-12)
    r, big_r = d_alpha * r_f, alpha_f * r_f
    full = 2 * r * big_r - (4 - math.pi) * r * r
    for turned in (phi_1 + alpha_f + 0.01, phi_1 + phi_p - 0.01):
        assert valve_plate_opening(_start(turned), 0.0, *PLATE) == pytest.approx(full, rel=1e-12)
        assert valve_plate_opening(_start(turned, math.pi) + 2 * math.pi, math.pi, *PLATE) == pytest.approx(full)
    end = phi_1 + phi_p + alpha_f + phi_2
    assert valve_plate_opening(_start(end + 0.01), 0.0, *PLATE) == 0.0
    assert valve_plate_opening(_start(0.5 * phi_1, start=1.0), 1.0, *PLATE) == pytest.approx(notch)
    # the same plate every turn, forwards and backwards
    for turned in (0.5 * phi_1, phi_1 + alpha_f + 0.01, end + 0.01, -0.5):
        area = valve_plate_opening(_start(turned, start=1.0), 1.0, *PLATE)
        for turns in (-2, -1, 1):
            again = valve_plate_opening(_start(turned, start=1.0) + 2 * math.pi * turns, 1.0, *PLATE)
            assert again == pytest.approx(area, rel=1e-9, abs=1e-18)
    # Hopsan's measure (periodic false): shut before the bore first reaches the notch, a negative angle as
    # 2π - fmod(|θ| - start - α_min, 2π)
    hopsan = {"periodic": False}
    assert valve_plate_opening(_start(-0.01, start=1.0), 1.0, *PLATE, **hopsan) == 0.0  # not reached yet
    # port B of bore 1 at a small positive angle: in its second notch a turn on, which Hopsan's plate has not reached
    late = _start(end - 0.1 - 2 * math.pi, start=math.pi)
    assert late >= 0.0 and valve_plate_opening(late, math.pi, *PLATE) > 0.0
    assert valve_plate_opening(late, math.pi, *PLATE, **hopsan) == 0.0
    assert valve_plate_opening(_start(0.5 * phi_1) + 2 * math.pi, 0.0, *PLATE, **hopsan) == pytest.approx(notch)
    mirrored = -(2 * math.pi - _start(0.5 * phi_1)) - 2 * (math.pi / 2 - phi_p / 2 - phi_1 - d_alpha)
    assert valve_plate_opening(mirrored, 0.0, *PLATE, **hopsan) == pytest.approx(notch)


def test_swash_plate_piston_strokes_by_r_tan_gamma_and_its_arm_is_its_velocity_per_speed() -> None:
    """x = r tan γ sin(-θ - φ), ẋ = -r tan γ cos(-θ - φ) ω: the velocity is the derivative of the stroke along
    θ(t) = ω t, and the arm ∂x/∂θ is ẋ/ω."""
    r, gamma, phase, omega = 0.04, 0.2, 0.7, 150.0
    t = np.linspace(0.0, 0.05, 2001)
    x, v, arm = swash_plate_piston(omega * t, omega, r, gamma, phase)
    np.testing.assert_allclose(x, r * math.tan(gamma) * np.sin(-omega * t - phase), rtol=1e-12)
    np.testing.assert_allclose(np.gradient(x, t)[1:-1], v[1:-1], atol=1e-3 * r * math.tan(gamma) * omega)
    np.testing.assert_allclose(arm * omega, v, rtol=1e-12)


def test_a_swash_plate_block_turns_under_its_torque_and_strokes_its_pistons() -> None:
    """Turned by 2 N m against B = 4 (J 0.5) with the plate tilted and no piston pushing: ω = 0.5 (1 - e^(-8t)),
    the k-th of three pistons at r tan γ sin(-θ - offset - 2π(k-1)/3). A force of 100 N on piston 2's foot turns
    the block at rest as J ω' = 100 ∂x_2/∂θ."""
    s = System("block")
    s.add(c.SwashPlate("b", pistons=3, J=0.5, B_rot=4.0, r=0.05, angle=0.3, theta_offset=0.4))
    s.add(c.TorqueSource("t"))
    s.add(c.Constant("T", unit="N*m", value=-2.0))  # the source's outward torque presses on the port: -T turns it
    s.connect("T.y", "t.u")
    s.connect("t.P", "b.P2")
    t = np.array([0.0, 0.1, 0.5])
    res = s.simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    omega = 0.5 * (1.0 - np.exp(-8.0 * t))
    theta = 0.5 * (t - (1.0 - np.exp(-8.0 * t)) / 8.0)
    np.testing.assert_allclose(res["b.omega"], omega, atol=1e-7)
    np.testing.assert_allclose(res["b.movement"], -omega, atol=1e-7)
    for k in (1, 2, 3):
        a = -theta - 0.4 - 2 * math.pi * (k - 1) / 3
        np.testing.assert_allclose(res[f"b.x{k}"], 0.05 * math.tan(0.3) * np.sin(a), atol=1e-8)
        np.testing.assert_allclose(res[f"b.v{k}"], -0.05 * math.tan(0.3) * np.cos(a) * omega, atol=1e-7)
    s = System("pushed")
    s.add(c.SwashPlate("b", pistons=3, J=0.5, B_rot=0.0, r=0.05, angle=0.3, theta_offset=0.4))
    s.add(c.ForceSource("f"))
    s.add(c.Constant("F", unit="N", value=-100.0))
    s.connect("F.y", "f.u")
    s.connect("f.P", "b.C2")
    res = s.simulate(t_eval=[0.0, 1e-4], accuracy=1e-10, method="cvodes")
    arm = -0.05 * math.tan(0.3) * math.cos(-0.4 - 2 * math.pi / 3)
    assert res["b.omega"][1] == pytest.approx(100.0 * arm / 0.5 * 1e-4, rel=1e-5)
    with pytest.raises(ParameterError, match="pistons"):
        c.SwashPlate("b", pistons=0)


def _piston(q: float, **values: float) -> System:
    s = System("piston")
    s.add(c.PumpPiston("p", A_1=2e-4, s_l=0.1, V_1=5e-6, B_p=10.0, beta_e=1e9, F_0=500.0, **values))
    s.add(c.FixedPosition("wall"))
    s.add(c.FlowSource("q", q=q))
    s.connect("p.P3", "wall.P")
    s.connect("q.P", "p.P1")
    return s


def test_a_pump_piston_builds_pressure_in_its_bore_and_presses_its_foot_out() -> None:
    """A foot held at x = 0: the chamber of V = V_1 + A_1 s_l/2 filled at 1e-6 m³/s rises as β Q t/V, and the
    piston presses out with A_1 (p - p_amb) + F_0; with no inflow its leakage c_leak (p - p_case) lets the
    pressure fall as e^(-β c_leak t/V) to p_case; drawn from, it holds at p_floor."""
    V = 5e-6 + 2e-4 * 0.05
    res = _piston(1e-6, c_leak=0.0, p_amb=-1e5).simulate(t_eval=[0.0, 1e-3], accuracy=1e-10, method="cvodes")
    assert res["p.p"][1] == pytest.approx(1e9 * 1e-6 * 1e-3 / V, rel=1e-8)
    assert res["p.F"][1] == pytest.approx(2e-4 * (res["p.p"][1] + 1e5) + 500.0, rel=1e-10)
    assert res["p.V"][1] == pytest.approx(V)
    s = _piston(0.0, c_leak=1e-12, p0=1e7, p_case=1e6)
    res = s.simulate(t_eval=[0.0, 0.01], accuracy=1e-10, method="cvodes")
    assert res["p.p"][1] - 1e6 == pytest.approx(9e6 * math.exp(-1e9 * 1e-12 * 0.01 / V), rel=1e-7)
    res = _piston(-1e-6, c_leak=0.0, p0=1e5, p_floor=-9e4).simulate(t_eval=[0.0, 0.1], method="cvodes")
    assert res["p.p"][1] == pytest.approx(-9e4, abs=10.0)


def test_a_pump_pistons_chamber_shrinks_as_its_foot_is_pushed_in() -> None:
    """Pushed in at 0.1 m/s (its foot's outward velocity -0.1) with its port closed, the chamber's volume
    V_1 + A_1 (s_l/2 + x) shrinks and its pressure rises as β ln(V_0/V)."""
    s = System("pushed")
    s.add(c.PumpPiston("p", A_1=2e-4, s_l=0.1, V_1=5e-6, B_p=0.0, beta_e=1e9, F_0=0.0, c_leak=0.0))
    s.add(c.VelocitySource("v"))
    s.add(c.Constant("u", unit="m/s", value=0.1))
    s.connect("u.y", "v.u")
    s.connect("p.P3", "v.P")
    res = s.simulate(t_eval=[0.0, 0.05], accuracy=1e-10, method="cvodes")
    v0 = 5e-6 + 2e-4 * 0.05
    assert res["p.V"][1] == pytest.approx(v0 - 2e-4 * 0.005, rel=1e-8)
    assert res["p.p"][1] == pytest.approx(1e9 * math.log(v0 / res["p.V"][1]), rel=1e-6)


def test_a_valve_plate_meters_each_bore_to_the_port_it_faces_as_a_turbulent_orifice() -> None:
    """Three bores at 12, 4 and 1 MPa, A at 2 MPa, B at 0: at θ = 0 (movement 0) each bore meets A or B through
    its opening; each flow is C_d A √(2/ρ) Δp/(Δp² + p_tr²)^¼ from the bore, the plate's flows sum to 0, and
    at a turned angle the openings are the law's."""
    plate = c.ValvePlate("vp", pistons=3, phi_P=PLATE[0], Delta_alpha=PLATE[1], alpha_f=PLATE[2], phi_1=PLATE[3],
                         phi_2=PLATE[4], theta_1=PLATE[5], theta_2=PLATE[6], R_f=PLATE[7], rho=876.0)
    p = plate.values
    pressures = {"p1": 12e6, "p2": 4e6, "p3": 1e6, "pA": 2e6, "pB": 0.0}
    for theta in (0.3, 2.0, 4.5):
        out = plate.output_equations(0.0, {"theta": theta}, {**pressures, "movement": 0.0}, p)
        total = out["QA"] + out["QB"]
        for k in (1, 2, 3):
            start = 2 * math.pi * (k - 1) / 3
            area_a = valve_plate_opening(theta, start, *PLATE)
            area_b = valve_plate_opening(theta, start + math.pi, *PLATE)
            assert out[f"A_A{k}"] == pytest.approx(area_a) and out[f"A_B{k}"] == pytest.approx(area_b)
            flow = 0.0
            for area, port in ((area_a, "pA"), (area_b, "pB")):
                dp = pressures[f"p{k}"] - pressures[port]
                flow += 0.67 * area * math.sqrt(2 / 876.0) * dp / (dp * dp + 50.0**2) ** 0.25
            assert out[f"Q{k}"] == pytest.approx(-flow, rel=1e-12, abs=1e-18)
            total += out[f"Q{k}"]
        assert abs(total) < 1e-15
    assert plate.state_equations(0.0, {"theta": 0.0}, {"movement": 150.0}, p, {}) == {"theta": 150.0}


def test_a_swash_plate_drive_strokes_its_pistons_at_the_speed_it_is_given() -> None:
    """SwashPlateDrive: θ' = -movement, piston k's foot at x_0 + r tan γ sin a_k, moving at -r tan γ cos a_k θ'
    (a_k = -θ - θ_offset - 2π(k-1)/N), whatever the forces on its ports."""
    drive = c.SwashPlateDrive("sp", pistons=4, r=0.04, angle=0.15, theta_offset=0.2, x0=0.01)
    p = drive.values
    theta, movement = 1.3, -25.0
    out = drive.output_equations(0.0, {"theta": theta}, {"movement": movement, **{f"F{k}": 1e3 * k for k in range(1, 5)}}, p)
    for k in range(1, 5):
        a = -theta - 0.2 - 2 * math.pi * (k - 1) / 4
        assert out[f"x{k}"] == pytest.approx(0.01 + 0.04 * math.tan(0.15) * math.sin(a), rel=1e-12)
        assert out[f"v{k}"] == pytest.approx(-0.04 * math.tan(0.15) * math.cos(a) * -movement, rel=1e-12)
    assert drive.state_equations(0.0, {"theta": theta}, {"movement": movement}, p, out) == {"theta": 25.0}
    assert set(drive.MECHANICAL) == {"C1", "C2", "C3", "C4"} and drive.config() == {"pistons": 4}
