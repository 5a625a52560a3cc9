"""One fluid per circuit: components take the oil's properties unless set on the component."""

from __future__ import annotations

import tomllib

import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.errors import ModelFileError, ParameterError
from hydroservo.fluids import get_fluid
from hydroservo.io.model_file import model_to_toml, system_from_dict


def circuit() -> System:
    s = System("fluid")
    s.add(c.FourWayValve("valve"))
    s.add(c.Cylinder("cyl", beta_e="1 GPa"))  # set on the component: kept
    return s


def test_components_take_the_fluids_properties_at_its_temperature_unless_set_on_them():
    s = circuit()
    s.set_fluid("iso-vg46", "60 degC")
    oil = get_fluid("iso-vg46")
    assert s["valve"].values["nu"] == pytest.approx(float(oil.kinematic_viscosity(0.0, 60.0)), rel=1e-12)
    assert s["valve"].values["rho"] == pytest.approx(float(oil.density(0.0, 60.0)), rel=1e-12)
    assert s["cyl"].values["rho"] == s["valve"].values["rho"]
    assert s["cyl"].values["beta_e"] == 1e9
    # a component added later takes it too; a changed fluid reaches every component not set by hand
    s.add(c.Volume("v"))
    assert s["v"].values["beta_e"] == pytest.approx(float(oil.bulk_modulus(0.0, 60.0)))
    s.set_fluid("iso-vg46", "20 degC", bulk_modulus="1.2 GPa")
    assert s["v"].values["beta_e"] == 1.2e9 and s["cyl"].values["beta_e"] == 1e9
    assert s["valve"].values["nu"] > 3 * float(oil.kinematic_viscosity(0.0, 60.0))  # colder oil is thicker


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"name": "water"}, "fluid 'water': unknown; built-in fluids: skydrol, iso-vg32, iso-vg46"),
        ({"name": "skydrol", "temperature": "300 degC"}, "more than 50 K outside the range of its model"),
        ({"name": "skydrol", "temperature": "20 bar"}, "fluid temperature"),
        ({"name": "skydrol", "bulk_modulus": "-1 GPa"}, "expected a positive pressure"),
    ],
)
def test_a_bad_fluid_is_refused_and_changes_nothing(kwargs, message):
    s = circuit()
    before = s.parameter_values()
    with pytest.raises(ParameterError, match=message):
        s.set_fluid(**kwargs)
    assert s.parameter_values() == before and s.fluid is None


def test_model_files_name_the_fluid_once_and_read_back_the_same_values():
    s = circuit()
    s.set_fluid("skydrol", "40 degC", bulk_modulus="1.3 GPa")
    text = model_to_toml(s)
    assert '[fluid]\nname = "skydrol"\ntemperature = "40 degC"\nbulk_modulus = "1.3 GPa"' in text
    assert "# nu = " in text and "from the circuit fluid" in text  # not pinned on the component
    back = system_from_dict(tomllib.loads(text))
    assert back.parameter_values() == s.parameter_values()
    back.set_fluid("skydrol", "0 degC")  # the read-back model still follows its fluid
    assert back["valve"].values["nu"] > 2 * s["valve"].values["nu"]


def test_a_bad_fluid_table_in_a_model_file_names_the_section():
    with pytest.raises(ModelFileError, match=r"\[fluid\] colour: unknown; expected name, temperature"):
        system_from_dict({"fluid": {"name": "skydrol", "colour": "red"}, "components": {"v": {"type": "Volume"}}})
    with pytest.raises(ModelFileError, match=r"\[fluid\]: expected a table with a name"):
        system_from_dict({"fluid": "skydrol", "components": {"v": {"type": "Volume"}}})
