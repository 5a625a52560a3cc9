"""Model files (hydroservo.io.model_file): bad files are refused with the component and parameter named."""

from __future__ import annotations

import pytest

from hydroservo.data import example_files
from hydroservo.errors import ModelFileError
from hydroservo.io import read_model

VALVE_CYLINDER = example_files()["valve_cylinder.toml"]


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda t: t.replace('p = "210 bar"', 'p = "210 bar'), "malformed TOML"),
        (lambda t: t.replace('type = "Tank"', 'type = "Sink"'), r"\[components.tank\]: unknown component type 'Sink'"),
        (
            lambda t: t.replace('A_A = "19.63 cm^2"', 'A_A = "3 bar"'),
            r"\[components.cyl\]: cyl.A_A: '3 bar' has the wrong dimension",
        ),
        (lambda t: t.replace('m = "250 kg"', 'm = "-250 kg"'), r"load.m = '-250 kg'.*expected > 0 kg"),
        (lambda t: t.replace('V_A0 = "0.3 L"', 'V_A0 = "-0.3 L"'), r"cyl.V_A0 = '-0.3 L'"),
        (lambda t: t.replace('"cyl.x" = "load.x"', '"cyl.x" = "load.position"'), "has no output 'position'"),
        (lambda t: t.replace('B = "2000 N*s/m"', 'Bee = "2000 N*s/m"'), "unknown parameter"),
    ],
)
def test_bad_model_files(tmp_path, edit, message) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(edit(VALVE_CYLINDER))
    with pytest.raises(ModelFileError, match=message):
        read_model(path)


def test_notes_are_read_written_and_printed_with_every_run(tmp_path) -> None:
    """A model file's [model] notes (a known discrepancy, a flagged peak its source has too) survive export and
    reload, and the simulate report prints them (text and JSON); anything but a list of texts is refused."""
    import hydroservo as hs
    from hydroservo.io import model_to_toml
    from hydroservo.workflows import simulate

    system = hs.load_model("position-servo")
    assert system.notes and "Hopsan's own result" in system.notes[0]
    path = tmp_path / "servo.toml"
    path.write_text(model_to_toml(system), encoding="utf-8")
    assert read_model(path).notes == system.notes
    report = simulate.run(path, t_end="0.01 s", points=11, write="none")
    # a run shorter than the default is not the run the notes were measured on: they are shown scoped to it
    scope = "[measured on the model's default run; this run changes t_end 0.01 s, points 11, so it may not hold here] "
    assert f"note: {scope}{system.notes[0]}" in report.lines()
    assert report.to_dict()["notes"] == [scope + note for note in system.notes]
    bad = tmp_path / "bad.toml"
    bad.write_text(path.read_text(encoding="utf-8").replace("notes = [", "notes = 3 # [", 1), encoding="utf-8")
    with pytest.raises(ModelFileError, match=r"\[model\] notes = 3: expected a list of texts"):
        read_model(bad)


def test_a_description_with_line_breaks_and_control_characters_is_written_as_valid_toml() -> None:
    """Hopsan's Dynamic Pressure Feedback describes itself in lines ending in CR: written raw they made the
    model file malformed TOML."""
    import tomllib

    from hydroservo.io.toml import toml_string

    for text in ('quote " and \\ backslash', "line 1\r\nline 2\ttab \x01 \x7f", "plain é"):
        assert tomllib.loads(f"k = {toml_string(text)}")["k"] == text
