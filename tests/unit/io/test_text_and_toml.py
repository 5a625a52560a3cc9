"""Terminal tables (io.text, by tabulate) and TOML values and edits (io.toml, by tomlkit)."""

from __future__ import annotations

import math
import tomllib

import pytest

from hydroservo.io.text import text_table
from hydroservo.io.toml import edit_toml, toml_key, toml_string, toml_value


def test_text_table_aligns_numbers_on_the_point_and_shows_missing_values() -> None:
    lines = text_table([["a", 1.5, None], ["bb", -12.25, "x"]], ["name", "value", "note"], indent=2)
    assert all(line.startswith("  ") for line in lines)
    assert lines[0].split() == ["name", "value", "note"] and set(lines[1].strip()) <= {"-", " "}
    points = {line.index(".") for line in lines[2:]}
    assert len(points) == 1  # 1.5 and -12.25 aligned on their decimal point
    assert lines[2].rstrip().endswith("-")  # None


@pytest.mark.parametrize("text", ['quote " and back\\slash', "two\nlines\r\n", "tab\tbell\x07", "µ³ °C"])
def test_toml_strings_read_back_as_written(text: str) -> None:
    # the hand-written writer left control characters unescaped: a description with a line break made a bad file
    assert tomllib.loads(f"k = {toml_string(text)}")["k"] == text


def test_toml_values_and_keys_read_back() -> None:
    value = {"a b": [1, 2.5e-10, "x"], "flag": True, "n": 3}
    assert tomllib.loads(f"{toml_key('cyl.pA')} = {toml_value(value)}") == {"cyl.pA": value}
    assert toml_value(0.1 + 0.2) == repr(0.1 + 0.2)  # full precision
    assert math.isnan(tomllib.loads(f"k = {toml_value(float('nan'))}")["k"])


def test_edit_toml_changes_adds_removes_and_renames_keeping_comments() -> None:
    text = '# head\n[a]  # table a\nx = 1  # the x\n# between\ny = 2\nold = 3  # renamed\n\n[b]\nz = "q"\n'
    out = edit_toml(text, {("a", "x"): "10", ("a", "y"): None, ("b", "w"): '"new"', ("a", "old"): "4"},
                    {("a", "old"): "new"})
    assert "# head" in out and "# table a" in out and "x = 10  # the x" in out and "# between" in out
    assert "new = 4  # renamed" in out and "y =" not in out
    assert tomllib.loads(out) == {"a": {"x": 10, "new": 4}, "b": {"z": "q", "w": "new"}}


def test_text_table_shows_no_negative_zero_and_nan_as_missing() -> None:
    lines = text_table([["a", -0.0, -0.00004, float("nan")]], ["n", "x", "y", "z"], digits=[5, 5, ".3f", 4])
    assert lines[2].split() == ["a", "0", "0.000", "-"]
