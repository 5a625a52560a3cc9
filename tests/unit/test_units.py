"""The shipped unit table (``data/units.json``) is pint's answers, complete, and used without the registry."""

from __future__ import annotations

import importlib.util
import itertools
import subprocess
import sys
from pathlib import Path

import pytest

from hydroservo.errors import ModelError
from hydroservo.system.expressions import check_dimension
from hydroservo.units import (
    Dimension,
    coherent_unit,
    dimension,
    from_si,
    parse_quantity,
    pint_entry,
    registry,
    si_unit,
    to_si,
    unit_table,
)

SHIPPED = unit_table()["units"]
SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "unit_table.py"


def test_every_shipped_entry_is_what_pint_computes() -> None:
    for unit, entry in SHIPPED.items():
        fresh = pint_entry(unit)
        assert fresh["factor"] == pytest.approx(entry["factor"], rel=1e-14), unit
        assert fresh["offset"] == pytest.approx(entry["offset"], rel=1e-14, abs=1e-12), unit
        assert (fresh["dimension"], fresh["coherent"], fresh["printed"]) == (
            entry["dimension"], entry["coherent"], entry["printed"]
        ), unit  # fmt: skip


def test_the_table_holds_every_unit_the_package_uses() -> None:
    # A new component, model file or common unit without its entry fails here: run scripts/unit_table.py.
    spec = importlib.util.spec_from_file_location("unit_table_script", SCRIPT)
    assert spec is not None and spec.loader is not None
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    assert sorted(SHIPPED) == script.collect()


@pytest.mark.parametrize(
    ("text", "unit"),
    [("1500 psi", "Pa"), ("25.5 L/min", "m^3/s"), ("3000 lbf", "N"), ("40 degC", "K"), ("104 degF", "degC"),
     ("313.15 K", "degC"), ("1 bar_abs", "Pa"), ("14.7 psia", "bar"), ("5 %", ""), ("0.1149 L/min/bar^0.5",
     "m^3/s/Pa^0.5"), ("32 cSt", "m^2/s"), ("1.2 in", "mm"), ("2.5 ms", "s")],
)  # fmt: skip
def test_a_conversion_between_shipped_units_equals_pints(text: str, unit: str) -> None:
    fast = to_si(text, unit)
    assert fast == pytest.approx(float(parse_quantity(text).to(registry().Unit(unit)).magnitude), rel=1e-13)
    magnitude, source = text.split(" ", 1)
    assert from_si(fast, unit, source) == pytest.approx(float(magnitude), rel=1e-13)


def test_dimension_arithmetic_follows_pint() -> None:
    for a, b in itertools.product(["Pa", "m^3/s", "N", "m", "kg", "1/s", ""], repeat=2):
        da, db = dimension(a), dimension(b)
        assert da is not None and db is not None
        qa, qb = registry().Quantity(1.0, a), registry().Quantity(1.0, b)
        assert da * db == Dimension(dict((str(k), v) for k, v in (qa * qb).dimensionality.items()))
        assert da / db**0.5 == Dimension(dict((str(k), v) for k, v in (qa / qb**0.5).dimensionality.items()))
    with pytest.raises(ValueError, match="cannot add"):
        dimension("m") + dimension("Pa")  # type: ignore[operator]
    assert dimension("furlongz") is None
    assert (coherent_unit("mm"), coherent_unit("bar"), si_unit("m^3/s")) == ("m", "Pa", "m³/s")


@pytest.mark.parametrize(
    ("expr", "declared", "message"),
    [("load.x + cyl.pA", "m", "mixes quantities of different dimensions"),
     ("load.x", "bar", "is a quantity of dimension"), ("sin(load.x)", "", "mixes quantities")],
)  # fmt: skip
def test_an_alias_of_unlike_dimensions_is_refused_with_pints_words(expr: str, declared: str, message: str) -> None:
    units = {"load.x": "m", "cyl.pA": "Pa", "cyl.A_A": "m^2"}
    with pytest.raises(ModelError, match=message):
        check_dimension(expr, units, declared, what="alias a")
    check_dimension("cyl.pA * cyl.A_A / 1000", units, "kN")  # like dimensions pass


def test_a_built_in_model_runs_without_building_the_registry() -> None:
    code = (
        "import sys, hydroservo as hs\n"
        "for name in ('flight-simulator', 'servo-solenoid-cylinder', 'robot-arm', 'position-servo'):\n"
        "    r = hs.load_model(name).simulate()\n"
        "    r.summary(); r.get(r.panels[0][0], r.units[r.panels[0][0]])\n"
        "print('pint' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


# -- display units (UnitChoice): what a review found ----------------------------------------------------------------
def test_angles_keep_their_own_dimension_in_a_choice_of_units() -> None:
    from hydroservo.errors import UnitError
    from hydroservo.units import UnitChoice, inferred_units

    # pint counts an angle as nothing: cm^3/rev would pass for a volume and Hz for rad/s (a factor 2 pi off)
    choice = inferred_units(["25 cm^3/rev", "4 L", "1500 rpm"])
    assert choice.unit("acc.V_oil", "m^3") == "L" and choice.unit("pump.D", "m^3/rev") == "cm^3/rev"
    with pytest.raises(UnitError, match="not a unit of speed"):
        UnitChoice.parse("speed=Hz")
    assert UnitChoice.parse("speed=rpm").unit("motor.omega", "rad/s") == "rpm"
    assert UnitChoice.parse("Hz").unit("motor.omega", "rad/s") == "rad/s"


def test_a_model_that_asks_for_si_gives_way_to_the_user() -> None:
    from hydroservo.units import UnitChoice

    model = UnitChoice.parse("si")
    assert UnitChoice.parse("bar").over(model).unit("cyl.pA", "Pa") == "bar"
    assert UnitChoice.parse("si").over(UnitChoice.parse("bar")).unit("cyl.pA", "Pa") == "Pa"


def test_a_length_brings_its_velocities_and_accelerations() -> None:
    from hydroservo.units import UnitChoice

    choice = UnitChoice.parse("mm, a=m/s^2")
    assert (choice.unit("x", "m"), choice.unit("v", "m/s"), choice.unit("a", "m/s^2")) == ("mm", "mm/s", "m/s^2")
