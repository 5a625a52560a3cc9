"""The first-principles two-stage servovalve as a component ([GordicND]): at rest, in motion, at every fidelity."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.analysis.servovalve import first_stage_null, table1
from hydroservo.components import ConstantPressure, Square, Step, Tank, TwoStageServovalve
from hydroservo.errors import ParameterError

RATED = 0.01  # A, Table 1


def no_load(valve: TwoStageServovalve, current: object, p_s: float = 209e5) -> hs.System:
    """The valve between 209 bar (gauge: 210 bar absolute) and tank, both use ports at half supply (eq. 57)."""
    s = hs.System("bench")
    s.add(valve)
    s.add(current)  # type: ignore[arg-type]
    s.add(ConstantPressure("ps", p=p_s))
    s.add(Tank("tank"))
    s.add(ConstantPressure("pa", p=p_s / 2))
    s.add(ConstantPressure("pb", p=p_s / 2))
    s.connect(f"{current.name}.y", f"{valve.name}.i")  # type: ignore[attr-defined]
    for port, node in (("P", "ps.P"), ("T", "tank.P"), ("A", "pa.P"), ("B", "pb.P")):
        s.connect(f"{valve.name}.{port}", node)
    return s


def test_at_rest_it_agrees_with_a_hand_written_scipy_implementation() -> None:
    """The bench's static test (the component's trim) against benchmarks/reference_servovalve.py: the same
    equations written out by hand with NumPy, solved by scipy.optimize.root, at 41 currents."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[4] / "benchmarks"))
    import bench_servovalve

    from hydroservo.analysis.servovalve_bench import static_tests

    flows = bench_servovalve.scipy_static(41)
    assert np.max(np.abs(static_tests(points=41).flows - flows)) < 1e-9 / 6e4  # L/min


def test_flapper_reaches_the_nozzle_at_25_percent_only() -> None:
    """[GordicND] section 4, Fig. 9: at a 10 Hz square wave of 5 and 10 % of rated current the flapper stays off
    the nozzles; at 25 % it reaches one (|x| = x_0 = 38.5 um), which slows the response."""
    peaks = {}
    for frac in (0.05, 0.10, 0.25):
        s = no_load(TwoStageServovalve("sv"), Square("cur", unit="A", amplitude=frac * RATED, frequency=10.0))
        r = s.simulate(0.15, n_points=1501)
        peaks[frac] = float(np.max(np.abs(r["sv.x"])))
    x0 = 38.5e-6
    assert peaks[0.05] < 0.5 * x0 and peaks[0.10] < 0.85 * x0
    assert peaks[0.25] > 0.999 * x0


@pytest.mark.parametrize("first_stage", ["quasi-static", "compressible"])
@pytest.mark.parametrize("flapper", ["bent", "rigid"])
def test_every_rung_runs_and_conserves_oil(first_stage: str, flapper: str) -> None:
    """At rest, what supply gives leaves through A, B and the return (the first stage's volumes are steady)."""
    valve = TwoStageServovalve("sv", first_stage=first_stage, flapper=flapper)
    s = no_load(valve, Step("cur", unit="A", amplitude=0.3 * RATED))
    r = s.simulate(0.03, n_points=301)
    QS, QT, QA, QB = (r[f"sv.{k}"][-1] for k in ("QS", "QT", "QA", "QB"))
    assert QS - QT - QA - QB == pytest.approx(0.0, abs=1e-6 * QS)
    assert QA == pytest.approx(-QB, rel=1e-6)
    assert 2.5 / 6e4 < QA < 4.5 / 6e4  # about 30 % of 12 L/min
    assert ("sv.x" in valve.ALGEBRAIC) is False and (("x" in valve.ALGEBRAIC) == (flapper == "bent"))
    assert ("p_l" in valve.STATES) == (first_stage == "compressible")


def test_the_bent_flapper_is_solved_at_every_output_time() -> None:
    """Eq. 14 holds along a transient: the tip is the armature's rotation less the jets' bending, and the bending
    is not negligible (the paper's point against x = theta l_a)."""
    from hydroservo.laws.armature import flapper_tip

    valve = TwoStageServovalve("sv")
    s = no_load(valve, Square("cur", unit="A", amplitude=0.1 * RATED, frequency=10.0))
    r = s.simulate(0.1, n_points=1001)
    v = valve.values
    tip = flapper_tip(r["sv.theta"], r["sv.F_h"], v["l_a"], v["l_fl"], v["B_fl"], v["l_t"], v["B_t"])
    assert np.max(np.abs(r["sv.x"] - tip)) < 1e-14  # m: Newton's solution, to round-off
    bending = np.abs(r["sv.theta"] * v["l_a"] - r["sv.x"])
    assert np.max(bending) > 0.2 * np.max(np.abs(r["sv.x"]))


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"l_a": 14e-3}, "pivot must lie within the flapper"),
        ({"F_cn": 5e-3}, "sliding friction above the static"),
        ({"K_f": -1.0}, "sv.K_f = -1 N/m: expected > 0"),
        ({"x_0": 0.0}, "sv.x_0 = 0 m: expected > 0"),
    ],
)
def test_a_servovalve_no_one_could_build_is_refused(changes: dict, message: str) -> None:
    with pytest.raises(ParameterError, match=message):
        valve = TwoStageServovalve("sv", **changes)
        no_load(valve, Step("cur", unit="A")).build()


def test_default_null_coefficients_are_lichtarowicz_at_210_bar() -> None:
    """K_o0 and K_od0 default to the constant and drain orifices' coefficients at null at 210 bar, to the three
    digits declared (analysis.servovalve.first_stage_null solves them)."""
    null = first_stage_null(210e5, table1())
    spec = TwoStageServovalve.PARAMETERS
    assert spec["K_o0"].default == pytest.approx(null["K_o"], abs=5e-4)
    assert spec["K_od0"].default == pytest.approx(null["K_od"], abs=5e-4)


@pytest.mark.slow  # about 5 s (the default suite stays inside its 5 minutes)
def test_the_amplifier_of_eqs_1_2_drives_it_in_a_system() -> None:
    """Eq. 1: i = sat(K_a U); eq. 2 adds electrical feedback of the spool, U - K_p y. The package's Amplifier
    (saturating) and Sum in front of the valve: a command that would ask 30 mA is held at the 12 mA limit,
    and the feedback of the spool position lowers the current the valve settles at."""
    from hydroservo.components import Amplifier, Gain, Sum

    def run(k_p: float) -> hs.Result:
        s = hs.System("driven")
        s.add(TwoStageServovalve("sv"))
        s.add(Step("u", unit="V", amplitude=3.0))
        s.add(Sum("err", unit="V"))
        s.add(Gain("kp", unit="V", input_unit="m", K=k_p))
        s.add(Amplifier("amp", G_a=1.0, R=100.0, I_max=0.012))  # 10 mA/V: 3 V asks 30 mA
        for name, p in (("ps", 209e5), ("pa", 104.5e5), ("pb", 104.5e5)):
            s.add(ConstantPressure(name, p=p))
        s.add(Tank("tank"))
        s.connect("u.y", "err.u1")
        s.connect("kp.y", "err.u2")
        s.connect("sv.y", "kp.u")
        s.connect("err.y", "amp.E")
        s.connect("amp.i", "sv.i")
        for port, node in (("P", "ps.P"), ("T", "tank.P"), ("A", "pa.P"), ("B", "pb.P")):
            s.connect(f"sv.{port}", node)
        return s.simulate(0.05, n_points=51)

    open_loop, closed = run(0.0), run(5000.0)  # 5000 V/m: 0.44 mm of spool feeds back 2.2 V
    assert open_loop["amp.i"][-1] == pytest.approx(0.012, rel=1e-9)
    assert closed["amp.i"][-1] < 0.012 and closed["sv.y"][-1] < open_loop["sv.y"][-1]
