"""A model's notes are true of the run they are shown with: as they are for the model's default run, said to be of
the default run (naming what this run changes) otherwise; and the report one sends a colleague carries them."""

from __future__ import annotations

import html
import warnings

import pytest

import hydroservo as hs
from hydroservo.workflows import report, simulate

SCOPED = "[measured on the model's default run; this run changes "


@pytest.fixture(scope="module")
def position_servo_report() -> report.ModelReport:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the flagged peaks the note is about
        return report.run("position-servo", validation=False)


def test_the_notes_of_the_default_run_are_shown_as_they_are() -> None:
    done = simulate.run("flight-simulator", write="none")
    assert done.departures == [] and done.notes() == hs.load_model("flight-simulator").notes
    assert any(line.startswith("note: With the dissertation's Appendix C values") for line in done.lines())


def test_a_note_is_not_shown_as_true_of_a_run_with_other_parameters() -> None:
    done = simulate.run("flight-simulator", sets=["load.W=3000 lbf"], write="none", cli=True)
    assert done.departures == ["load.W"]
    (note,) = done.notes()
    assert note.startswith(SCOPED + "load.W, so it may not hold here] ") and "about 1630 psi" in note
    assert done.to_dict()["notes"] == [note] and f"note: {note}" in done.lines()
    assert done.result.get("p1", "psi").max() == pytest.approx(1382, abs=2)  # the run's own, in its table


def test_a_note_is_not_shown_as_true_of_a_run_of_another_solver_and_accuracy() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        done = simulate.run("position-servo", method="dopri5", accuracy="1e-2", write="none", cli=True)
    assert done.departures == ["--method dopri5", "--accuracy 1e-2"]
    assert all(n.startswith(SCOPED + "--method dopri5, --accuracy 1e-2,") for n in done.notes())
    assert done.to_dict()["departures"] == ["--method dopri5", "--accuracy 1e-2"]


def test_a_system_changed_in_python_knows_what_it_changed_of_its_file() -> None:
    from hydroservo.io.notebook import departures

    system = hs.load_model("flight-simulator")
    assert departures(system) == []
    system.set("load.W", "3000 lbf")
    system.t_end = 1.0
    assert departures(system) == ["load.W", "t_end"]
    scoped = "[measured on the model's default run; this system changes load.W, t_end, so it may not hold here]"
    assert html.escape(scoped) in system._repr_html_()
    done = simulate.run(system, t_end="0.5 s", points=101, write="none")
    assert done.departures == ["load.W", "t_end", "t_end 0.5 s", "points 101"]


def test_the_report_of_position_servo_carries_its_note_and_its_validation_status(position_servo_report) -> None:
    page = position_servo_report.to_html()
    (note,) = hs.load_model("position-servo").notes
    assert "<h2>Notes</h2>" in page or ">Notes<" in page
    assert "in Hopsan&#x27;s own result too" in page and "within 0.0004 % of its range" in page
    assert "validation: piston position within 0.5 % of range" in page and "(published)" in page
    assert position_servo_report.simulation.notes() == [note]
