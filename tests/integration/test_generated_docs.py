"""The generated parts of the docs are what the code gives today (``python docs/tools/generated.py`` rewrites them).

The component reference (docs/components.md) and the glossary of docs/nomenclature.md come from the component
registry and the
tables of docs/validation.md from the validation rows, so that neither can
drift from the code; and one parameter name has one unit across components.
"""

from __future__ import annotations

import importlib.util
from collections import defaultdict
from pathlib import Path

import pytest

from hydroservo.components import REGISTRY

DOCS = Path(__file__).resolve().parents[2] / "docs"


def _tool():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("generated", DOCS / "tools" / "generated.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_component_reference_is_current() -> None:
    text = (DOCS / "components.md").read_text(encoding="utf-8")
    assert _tool().fill(text, _tool().component_reference()) == text, "run: python docs/tools/generated.py"
    for name in REGISTRY.types:  # every type has its section
        assert f"\n### {name}\n" in text, name


def test_nomenclature_is_current() -> None:
    text = (DOCS / "nomenclature.md").read_text(encoding="utf-8")
    assert _tool().fill(text, _tool().parts()) == text, "run: python docs/tools/generated.py"


@pytest.mark.slow
def test_validation_tables_are_current() -> None:
    text = (DOCS / "validation.md").read_text(encoding="utf-8")
    assert _tool().fill(text, _tool().validation_tables()) == text, "run: python docs/tools/generated.py"


def test_one_name_one_unit() -> None:
    units: dict[str, set[str]] = defaultdict(set)
    for cls in REGISTRY.types.values():
        for key, spec in cls.PARAMETERS.items():
            # a gain between a block's output and input units is a pure number when they are one unit
            units[key].add("" if spec.unit == "@/@in" else spec.unit)
    assert {k: u for k, u in units.items() if len(u) > 1} == {}
