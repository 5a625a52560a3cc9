"""The component reference (``hydroservo describe``, docs/components.md) says what the declarations say."""

from __future__ import annotations

import json

import pytest

from hydroservo.components import REGISTRY, Cylinder
from hydroservo.components.reference import _declarations, catalogue, reference, text
from hydroservo.errors import ParameterError


def test_every_type_is_described_with_every_declaration() -> None:
    refs = {r.name: r for r in catalogue()}
    assert set(refs) == set(REGISTRY.types)
    for name, cls in REGISTRY.types.items():
        ref = refs[name]
        declared = _declarations(cls)  # a line's states and ports: those of a default instance
        assert [p["name"] for p in ref.parameters] == list(cls.PARAMETERS), name
        assert [s["name"] for s in ref.states] == list(declared.STATES), name
        assert [p["name"] for p in ref.inputs] == list(declared.INPUTS), name
        assert [o["name"] for o in ref.outputs] == list(declared.OUTPUTS), name
        assert [h["name"] for h in ref.hydraulic] == list(declared.HYDRAULIC), name
        assert [o["name"] for o in ref.options] == list(cls.OPTIONS), name
        assert ref.summary and ref.notes.startswith(ref.summary.split("`")[0][:20]), name
        json.dumps(ref.to_dict())  # plain values: the CLI prints it as JSON


def test_cylinder_reference_gives_units_defaults_ranges_and_limits() -> None:
    ref = reference(Cylinder)
    area = next(p for p in ref.parameters if p["name"] == "A_A")
    assert (area["unit"], area["default"], area["range"]) == ("m²", 2e-3, "> 0")
    floor = next(p for p in ref.parameters if p["name"] == "p_floor")
    assert floor["range"] == "≥ -101325"
    assert {lim["signal"] for lim in ref.limits} == {"pA", "pB", "x", "VA", "VB"}
    shown = text(ref)
    assert "bulk_modulus = 'constant': one of constant, lee, eggerth" in shown
    assert "QA [m³/s]  flow into side A (must be connected)" in shown


def test_published_defaults_name_their_parameter_set() -> None:
    ref = reference("ServoSolenoidValve")
    k = next(p for p in ref.parameters if p["name"] == "k")
    assert k["default_from"].startswith("FerreiraND") and k["default"] > 0


def test_signal_blocks_take_their_unit_and_former_names_resolve() -> None:
    step = reference("Step")
    assert "unit" in step.arguments and next(p for p in step.parameters if p["name"] == "amplitude")["unit"] == "signal"
    assert reference("MareSpoolValve").name == "StagedSlotValve"
    with pytest.raises(ParameterError, match=r"component type 'Valve': unknown \(did you mean '\w+' or 'CheckValve' or 'TwoWayValve'\?\); known: .*Cylinder"):
        reference("Valve")


def test_equations_print_in_unicode_in_a_terminal_and_as_latex_in_the_docs() -> None:
    from hydroservo.components.reference import catalogue, markdown, text

    cyl = reference("Cylinder")
    shown = text(cyl)
    # a fraction a factor follows is bracketed, symbols side by side are spaced: no reading E'/(V_A (Q_A ...))
    assert "ṗ_A = [E'(p_A)/V_A](Q_A - A_A ẋ - Q_Li - Q_LeA),    V_A = V_A0 + k_V A_A x" in shown
    assert "ṗ_B = [E'(p_B)/V_B](" in shown  # an aligned block: one line per line
    assert "x‴_v = [K_2/A_v]ω_h^2 x_f - 2 δ_h ω_h ẍ_v" in text(reference("FlapperNozzleSpool"))
    for ref in catalogue():  # no LaTeX left in any terminal text: no \frac, no \dot, no :math:
        assert "\\" not in ref.notes and ":math:" not in ref.notes and ".. math::" not in ref.notes, ref.name
    page = markdown(cyl)
    assert "$$\n\\begin{aligned}\\dot p_A &= \\frac{E'(p_A)}{V_A}" in page  # MathJax renders it on the site
    assert "$Q_{Li} = C_{Li}(p_A - p_B)$" in page
