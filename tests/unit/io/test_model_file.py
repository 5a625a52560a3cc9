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
