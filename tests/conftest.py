"""Fixtures shared by the unit, integration and validation tests.

The suite runs with ``--import-mode=importlib`` (pyproject.toml), so test
modules cannot import one another: what several of them need lives here.
"""

from __future__ import annotations

import contextlib
import io
import shlex
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.analysis import FrequencyResponse
from hydroservo.analysis.static_bench import Bench
from hydroservo.cli import main
from hydroservo.components import StagedSlotValve
from hydroservo.data import example_files, parameter_set
from hydroservo.identification import spool_response
from hydroservo.io import read_staged_slot_valve
from hydroservo.laws import pseudo_section as ps
from hydroservo.validation import Check, validate
from hydroservo.validation.ferreira import bode_grid, published_dynamics

CliRun = Callable[..., tuple[int, str, str]]


@pytest.fixture(scope="session", autouse=True)
def compiled_models_cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    """Compiled models (``simulate(method="ros23")``, ...) go to a cache folder of the session's own, not the
    user's: the suite builds them afresh and leaves nothing behind."""
    import os

    folder = tmp_path_factory.mktemp("hydroservo-cache")
    before = os.environ.get("HYDROSERVO_CACHE")
    os.environ["HYDROSERVO_CACHE"] = str(folder)
    yield folder
    if before is None:
        os.environ.pop("HYDROSERVO_CACHE", None)
    else:
        os.environ["HYDROSERVO_CACHE"] = before


# -- the command line -----------------------------------------------------------
@pytest.fixture
def cli(capsys: pytest.CaptureFixture[str]) -> CliRun:
    """``cli("valve", "fit", ...)`` runs ``hydroservo valve fit ...`` in-process: (exit code, stdout, stderr)."""

    def run(*argv: str) -> tuple[int, str, str]:
        code = main(list(argv))
        out = capsys.readouterr()
        return code, out.out, out.err

    return run


@pytest.fixture
def command_line(monkeypatch: pytest.MonkeyPatch) -> Callable[[str], None]:
    """``command_line("cd out && hydroservo simulate x > out.txt")`` runs a documented command line as a shell
    would: ``cd`` as such, each ``hydroservo`` part through the CLI in-process (exit code 0 expected), ``> file``
    writing what it printed."""

    def run(line: str) -> None:
        for part in line.split("&&"):
            argv = shlex.split(part.strip())
            if argv[0] == "cd":
                monkeypatch.chdir(argv[1])
                continue
            assert argv[0] == "hydroservo", f"not a hydroservo command: {part.strip()!r}"
            target = None
            if ">" in argv:
                target = Path(argv[argv.index(">") + 1])
                argv = argv[: argv.index(">")]
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                try:
                    code = main(argv[1:])
                except SystemExit as exc:  # --version and --help answer by exiting
                    code = exc.code if isinstance(exc.code, int) else 1
            assert code == 0, f"{part.strip()!r} exited with {code}:\n{out.getvalue()}"
            if target is not None:
                target.write_text(out.getvalue(), encoding="utf-8")

    return run


# -- validation rows --------------------------------------------------------------
@pytest.fixture(scope="session")
def validated() -> Callable[[str], list[Check]]:
    """``validated(name)`` is ``hydroservo.validation.validate(name)``, computed once per session.

    The rows' tests (validation/test_rows.py) and the detailed tests of each source share one computation
    (about 5 s for servo-solenoid-cylinder). Checks are frozen; each call returns a new list.
    """
    cache: dict[str, list[Check]] = {}

    def get(name: str) -> list[Check]:
        if name not in cache:
            cache[name] = validate(name)
        return list(cache[name])

    return get


# -- small systems ----------------------------------------------------------------
@pytest.fixture
def driven() -> Callable[..., hs.System]:
    """A factory: ``block`` with its input ``port`` fed by the output ``y`` of ``source`` (t_end 1 s)."""

    def build(block: c.Component, source: c.Component, port: str = "u") -> hs.System:
        s = hs.System("driven", t_end=1.0)
        s.add(source)
        s.add(block)
        s.connect(f"{source.name}.y", f"{block.name}.{port}")
        return s

    return build


@pytest.fixture
def spring_mass() -> Callable[..., hs.System]:
    """A factory: a 2 kg mass on an 800 N/m spring released from 10 mm (omega_n = 20 rad/s), extra Mass values."""

    def build(**kw: object) -> hs.System:
        s = hs.System("spring-mass")
        s.add(c.Mass("load", m=2.0, k_spring=800.0, x0=0.01, incline=0.0, **kw))
        return s

    return build


@pytest.fixture
def rate_limited_spool_system() -> Callable[..., hs.System]:
    """A factory: the rate-limited spool of FerreiraND Fig. 11 (component defaults) driven by a sine ``u``."""

    def build(delay_model: str = "none") -> hs.System:
        s = hs.System("spool")
        s.add(c.Sine("u"))
        s.add(c.SpoolRateLimited("spool", delay_model=delay_model))
        s.connect("u.y", "spool.u")
        return s

    return build


@pytest.fixture
def valve_cylinder_file(tmp_path: Path) -> Path:
    """The example model file ``valve_cylinder.toml`` written to a temporary folder."""
    path = tmp_path / "vc.toml"
    path.write_text(example_files()["valve_cylinder.toml"])
    return path


# -- FerreiraND: the servo-solenoid valve -------------------------------------------
@pytest.fixture
def ferreira_published() -> dict[str, dict[str, float]]:
    """The pseudo-section parameters FerreiraND section 5 prints, per structure, in SI (parameter set FerreiraND)."""
    pset = parameter_set("FerreiraND")
    return {
        structure: {k: pset.si(structure, k, ps.PARAMETER_UNITS[k]) for k in ps.PARAMETER_NAMES[structure]}
        for structure in ("variable", "fixed")
    }


@pytest.fixture
def ferreira_printed() -> dict[str, dict[str, str]]:
    """The same parameters as printed ("0.1149 L/min/bar^0.5"), per structure."""
    pset = parameter_set("FerreiraND")
    return {
        structure: {k: str(pset.table(structure)[k]) for k in ps.PARAMETER_NAMES[structure]}
        for structure in ("variable", "fixed")
    }


@pytest.fixture(scope="session")
def published_bode() -> FrequencyResponse:
    """Bode data of the published spool dynamics (FerreiraND section 6) on the grid of Fig. 10.

    Twice the integration grid of the fit (512 steps per period), so that a fit does not see its own numbers.
    """
    amps, freqs = bode_grid()
    return spool_response(published_dynamics(), amps, freqs, steps_per_period=512)


# -- MareAttarND: the staged-slot valve (hydroservo's example geometry) -------------------------


@pytest.fixture(scope="session")
def aerospace_example() -> tuple[StagedSlotValve, Bench]:
    """The built-in staged-slot valve ``aerospace-example`` (parameter set MareAttarND_example) and its bench."""
    valve, bench = read_staged_slot_valve("aerospace-example")
    assert bench is not None
    return valve, bench


@pytest.fixture(scope="session")
def aerospace_valve(aerospace_example: tuple[StagedSlotValve, Bench]) -> StagedSlotValve:
    return aerospace_example[0]


@pytest.fixture(scope="session")
def aerospace_bench(aerospace_example: tuple[StagedSlotValve, Bench]) -> Bench:
    return aerospace_example[1]


@pytest.fixture(scope="session")
def staged_slot_start(tmp_path_factory: pytest.TempPathFactory) -> StagedSlotValve:
    """The start of the identification: the example ``guess.toml`` that ``hydroservo examples`` hands out,
    every identified parameter of the aerospace example 30-40 % away (docs/examples/make_example_files.py)."""
    path = tmp_path_factory.mktemp("examples") / "guess.toml"
    path.write_text(example_files()["guess.toml"])
    return read_staged_slot_valve(path)[0]


# -- rig records of the robot arm (calibration, identification) ------------------------------------
#: Parameters of the "rig" the synthetic records come from: the robot-arm model with these changed.
ARM_TRUTH = {"spool.tau": 0.024, "valve.c_v": 1.3e-4, "cyl.C_Li": 3e-13, "load.B": 350.0, "load.F_c0": 60.0}


def arm_with_steps(levels: tuple[float, ...] = (0.368, -0.5), hold: float = 0.5, rest: float = 0.4,
                   t_end: float = 4.0) -> hs.System:
    """The robot arm driven by held valve-signal steps on the 200 Hz grid (a record replays them exactly)."""
    from hydroservo.components.signals import Table
    from hydroservo.identification.rig import held_steps

    arm = hs.load_model("robot-arm")
    arm.t_end = t_end
    times, values = held_steps(levels, hold, rest=rest)
    times[-1] = max(times[-1], t_end)
    arm.replace(Table("command", times=times, values=values))
    return arm


def arm_record(seed: int = 3, *, params: dict | None = None, t_end: float = 4.0, sensors: tuple[str, ...] = ("cyl.pA", "cyl.pB", "load.x", "command.y")):
    """A record of the stepped robot arm at [Efe2014] Table 5.1's rates and typical noise."""
    from hydroservo.identification.rig import EFE_SENSORS, virtual_rig

    arm = arm_with_steps(t_end=t_end)
    return virtual_rig(arm, {s: EFE_SENSORS[s] for s in sensors}, params=ARM_TRUTH if params is None else params,
                       seed=seed, t_end=t_end, name=f"step-{seed}")


@pytest.fixture(scope="session")
def step_record():
    """One 4-s, two-rate record of the stepped robot arm (extend 36.8 %, retract 50 %) with ARM_TRUTH."""
    return arm_record()


@pytest.fixture(scope="session")
def arm_truth() -> dict[str, float]:
    return dict(ARM_TRUTH)


@pytest.fixture(scope="session")
def stepped_arm():
    """The model the records are fitted with: the robot arm as published (it does not know ARM_TRUTH)."""
    return arm_with_steps


@pytest.fixture(scope="session")
def make_arm_record():
    """``make_arm_record(seed, params=..., t_end=...)``: more records of the stepped robot arm."""
    return arm_record
