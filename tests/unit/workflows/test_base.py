"""What every workflow shares: a report's files written all or nothing, its page, errors named for who asked."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import pytest

from hydroservo.errors import ParameterError
from hydroservo.workflows.base import Artifact, Report, Workflow, load_with_sets, parse_sets


@dataclass
class _Two(Report):
    command: ClassVar[str] = "two"
    fail: bool = False

    def artifacts(self) -> list[Artifact]:
        def second(path: Path) -> None:
            if self.fail:
                raise RuntimeError("the second file cannot be written")
            path.write_text("b")

        return [Artifact("a", "a.txt", lambda p: p.write_text("a")), Artifact("b", "b.txt", second)]


def test_a_report_writes_all_its_files_or_none(tmp_path: Path) -> None:
    with pytest.raises(RuntimeError):
        _Two(fail=True).write(tmp_path / "out")
    assert not (tmp_path / "out").exists()  # nothing left behind, not even the folder
    files = _Two().write(tmp_path / "out")
    assert sorted(Path(p).name for p in files.values()) == ["a.txt", "b.txt"]
    with pytest.raises(ParameterError, match="a.txt, b.txt already exist"):
        _Two().write(tmp_path / "out")  # nothing replaced unasked
    assert _Two().write(tmp_path / "out", force=True) == files


def test_a_report_shows_itself_as_a_page_and_in_a_notebook_frame() -> None:
    report = _Two(warnings=["careful <now>"])
    page = report.to_html()
    assert page.startswith("<!DOCTYPE html>") and "careful &lt;now&gt;" in page
    frame = report._repr_html_()
    assert frame.startswith("<iframe srcdoc=") and "<!DOCTYPE" not in frame  # escaped inside the attribute


@dataclass
class _Job(Workflow):
    OPTIONS: ClassVar[dict[str, str]] = {"sets": "--set"}
    t_end: float = 1.0


def test_errors_name_an_input_as_its_caller_wrote_it() -> None:
    assert _Job().name("t_end") == "t_end"
    assert _Job(cli=True).name("t_end") == "--t-end" and _Job(cli=True).name("sets") == "--set"


def test_changes_to_a_model_are_checked_and_named() -> None:
    assert parse_sets({"load.W": "3000 lbf"}) == [("load.W", "3000 lbf")]
    assert load_with_sets("flight-simulator", ["load.W=3000 lbf"])["load"].given["W"] == "3000 lbf"
    with pytest.raises(ParameterError, match="sets load.mass=3 kg: 'load' has no parameter 'mass'"):
        load_with_sets("flight-simulator", {"load.mass": "3 kg"}, what="sets")
    with pytest.raises(ParameterError, match=r"--set 'load\.W': expected COMPONENT\.PARAMETER=VALUE"):
        parse_sets(["load.W"])


def test_a_simulation_takes_its_step_budget_from_the_caller() -> None:
    """Simulate(max_steps=...) (simulate --max-steps): the budget reaches the solver, whose failure names it."""
    from hydroservo.errors import SolverError
    from hydroservo.workflows.simulate import Simulate

    with pytest.raises(SolverError, match=r"step budget of 100 steps was used up"):
        Simulate("flight-simulator", max_steps=100, write="none").run()


def test_a_simulations_crossings_of_one_kind_in_one_component_are_told_in_one_line() -> None:
    """A ladder of many segments whose pressures all ring below vacuum is one warning naming its worst and how many
    more; a component with a few crossings keeps one line each; the JSON keeps every crossing."""
    from types import SimpleNamespace

    from hydroservo.system.plausibility import Implausible
    from hydroservo.workflows.simulate import GROUPED, _crossings

    def below(signal: str, value: float) -> Implausible:
        return Implausible(signal, 0.1, value, -2e5, "Pa", f"{signal} = {value:g} Pa: below vacuum")

    ladder = [below(f"line.p{k}", -3e5 - 1e3 * k) for k in range(GROUPED + 5)]
    few = [below(f"cyl.p{side}", -4e5) for side in "AB"]
    above = Implausible("line.p0", 0.2, 5e6, 3e6, "Pa", "line.p0 = 5e+06 Pa: above the source")
    lines = _crossings(SimpleNamespace(warnings=[*ladder, *few, above]))  # type: ignore[arg-type]
    assert lines[0].startswith(f"line.p{GROUPED + 4} = ") and f"and {GROUPED + 4} more signals of line below" in lines[0]
    assert lines[1:] == ["cyl.pA = -400000 Pa: below vacuum", "cyl.pB = -400000 Pa: below vacuum",
                         "line.p0 = 5e+06 Pa: above the source"]
