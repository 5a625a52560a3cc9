"""The FMU's model description (hydroservo.codegen.fmu): variables, value references, tunability, units, dependencies.

These tests build sources-only FMUs (no compiler needed) and read their modelDescription.xml; the
integration tests (tests/integration/test_fmu_fmpy.py) build binaries and run them in FMPy.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.codegen.fmu import export_fmu
from hydroservo.errors import ParameterError, UnitError


def _spring() -> hs.System:
    """A mass on a spring pushed by a step force: parameters that the rates use, and one only the start uses."""
    s = hs.System("spring")
    s.add(c.Mass("load", m=2.0, k_spring=800.0, x0=0.01, incline=0.0))
    s.add(c.Step("force", unit="N", amplitude=2.0, t_step=0.1))
    s.connect("force.y", "load.F_ext")
    return s


def _description(path: Path) -> ET.Element:
    with zipfile.ZipFile(path) as archive:
        return ET.fromstring(archive.read("modelDescription.xml"))


def _variables(root: ET.Element) -> list[ET.Element]:
    return list(root.find("ModelVariables") or [])


@pytest.fixture(scope="module")
def spring_fmu(tmp_path_factory: pytest.TempPathFactory):
    export = export_fmu(_spring(), tmp_path_factory.mktemp("fmu"), inputs=["load.F"], binary=False)
    return export, _description(export.path)


def test_variables_come_in_value_reference_order(spring_fmu) -> None:
    export, root = spring_fmu
    variables = _variables(root)
    assert [int(v.get("valueReference")) for v in variables] == list(range(len(variables)))
    kinds = [v.kind for v in export.variables]
    assert kinds == sorted(kinds, key=["parameter", "input", "state", "derivative", "output"].index)
    names = [v.get("name") for v in variables]
    assert names == [v.name for v in export.variables]
    assert export.inputs == ("load.F",) and export.states == ("load.x", "load.v")
    assert names[len(export.parameters) + 1 + 2 : len(export.parameters) + 1 + 4] == ["der(load.x)", "der(load.v)"]
    assert root.get("variableNamingConvention") == "structured"


def test_parameters_are_tunable_where_the_dynamics_use_them(spring_fmu) -> None:
    """load.m and load.k_spring enter the rates: tunable; load.x0 and load.v0 only the initial states: fixed."""
    export, root = spring_fmu
    variability = {v.get("name"): v.get("variability") for v in _variables(root) if v.get("causality") == "parameter"}
    assert variability["load.m"] == variability["load.k_spring"] == variability["force.amplitude"] == "tunable"
    assert variability["load.x0"] == variability["load.v0"] == "fixed"
    assert sum(export.tunable) == sum(1 for v in variability.values() if v == "tunable")


def test_each_variable_has_its_unit_start_and_range(spring_fmu) -> None:
    export, root = spring_fmu
    real = {v.get("name"): v.find("Real").attrib for v in _variables(root)}  # type: ignore[union-attr]
    assert real["load.m"]["unit"] == "kg" and float(real["load.m"]["start"]) == 2.0
    # The component's range: a mass above 0 (excluded); FMI's bounds are inclusive, so the least double above 0.
    assert float(real["load.m"]["min"]) == math.nextafter(0.0, 1.0) and "max" not in real["load.m"]
    assert float(real["load.k_spring"]["min"]) == 0.0  # included: a spring of 0 N/m is no spring
    assert real["load.F"] == {"unit": "N", "start": "0.0"}
    assert real["der(load.x)"]["unit"] == "m/s" and real["der(load.v)"]["unit"] == "m/s^2"
    assert int(real["der(load.v)"]["derivative"]) == [v.get("name") for v in _variables(root)].index("load.v") + 1
    units = {u.get("name"): u.find("BaseUnit") for u in root.find("UnitDefinitions") or []}
    assert set(units) == {r["unit"] for r in real.values() if "unit" in r}
    assert units["N"].attrib == {"kg": "1", "m": "1", "s": "-2"}  # type: ignore[union-attr]


def test_dependencies_are_the_models_sparsity(spring_fmu) -> None:
    """dx/dt = v depends on v only; dv/dt on x, v and the input force; the position output on itself."""
    export, root = spring_fmu
    index = {v.get("name"): str(i + 1) for i, v in enumerate(_variables(root))}
    structure = root.find("ModelStructure")
    assert structure is not None
    derivatives = {u.get("index"): u.get("dependencies", "").split() for u in structure.find("Derivatives") or []}
    assert derivatives[index["der(load.x)"]] == [index["load.v"]]
    assert sorted(derivatives[index["der(load.v)"]]) == sorted([index["load.x"], index["load.v"], index["load.F"]])
    outputs = {u.get("index"): u.get("dependencies", "").split() for u in structure.find("Outputs") or []}
    assert outputs[index["load.x"]] == [index["load.x"]]
    assert outputs[index["force.y"]] == []  # a function of time alone
    initial = [int(u.get("index", 0)) for u in structure.find("InitialUnknowns") or []]
    assert initial == sorted(initial) and int(index["load.x"]) in initial


def test_a_name_taken_by_a_parameter_gets_a_suffix(tmp_path: Path) -> None:
    """A supply's parameter p and its output p: FMI needs unique names, so the output is supply.p_out."""
    export = export_fmu(hs.load_model("flight-simulator"), tmp_path, binary=False)
    renamed = {v.signal: v.name for v in export.variables if v.name != v.signal and v.kind != "derivative"}
    assert renamed == {"supply.p": "supply.p_out", "tank.p": "tank.p_out"}
    names = [v.get("name") for v in _variables(_description(export.path))]
    assert len(names) == len(set(names))


def test_the_guid_is_the_contents(tmp_path: Path) -> None:
    """The same model gives the same GUID (reproducible builds); a changed start value another one."""
    first = export_fmu(_spring(), tmp_path / "a", binary=False)
    again = export_fmu(_spring(), tmp_path / "b", binary=False)
    heavier = _spring()
    heavier.set("load.m", 3.0)
    other = export_fmu(heavier, tmp_path / "c", binary=False)
    assert first.guid == again.guid != other.guid
    assert first.path.read_bytes() == again.path.read_bytes()
    with zipfile.ZipFile(first.path) as archive:
        assert f'"{first.guid}"' in archive.read("sources/spring_fmi2.c").decode()
        assert sorted(archive.namelist()) == sorted(first.files)


def test_a_sources_only_fmu_has_no_binaries(spring_fmu) -> None:
    export, root = spring_fmu
    assert export.platform is None and not any(f.startswith("binaries/") for f in export.files)
    for kind in ("ModelExchange", "CoSimulation"):
        element = root.find(kind)
        assert element is not None and element.get("modelIdentifier") == "spring"
        assert [f.get("name") for f in element.find("SourceFiles") or []] == ["spring.c", "spring_model.c", "spring_fmu_model.c", "spring_fmi2.c"]


def test_bad_arguments_are_refused_before_anything_is_written(tmp_path: Path) -> None:
    s = _spring()
    with pytest.raises(ParameterError, match="method 'euler'"):
        export_fmu(s, tmp_path, method="euler", binary=False)
    with pytest.raises(ParameterError, match="step '0 s'"):
        export_fmu(s, tmp_path, step="0 s", binary=False)
    with pytest.raises(UnitError):
        export_fmu(s, tmp_path, step="2 bar", binary=False)
    with pytest.raises(ParameterError, match="no input 'u'"):
        export_fmu(s, tmp_path, inputs=["load.u"], binary=False)
    with pytest.raises(ParameterError, match="C identifier"):
        export_fmu(s, tmp_path, name="2fast", binary=False)
    assert list(tmp_path.iterdir()) == []
    export_fmu(s, tmp_path, binary=False)
    with pytest.raises(ParameterError, match="spring.fmu already exist"):
        export_fmu(s, tmp_path, binary=False)
    export_fmu(s, tmp_path, binary=False, force=True)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["spring.fmu"]


HOSTILE_NAMES = {
    "injection": 'spring\n[initial]\n"load.x" = "50 mm"\n#',
    "control": "nul\x00esc\x1bbell\x07",
    "markup": 'a </fmiModelDescription> & "q" <!-- @NAME@ */ ??/ \\',
    "u2028": "line\u2028sep",
}


@pytest.mark.parametrize("name", list(HOSTILE_NAMES.values()), ids=list(HOSTILE_NAMES))
def test_a_model_named_anything_gives_a_model_description_that_reads_back(name: str, tmp_path: Path) -> None:
    """The name and description reach the XML through io.text.xml_text and ElementTree's escaping, and the C
    sources' comments and strings through _c_comment and _c_string: the FMU's files hold them and nothing else."""
    from hydroservo.io.text import xml_text

    system = _spring()
    system.name, system.description = name, name
    system.alias("y", "-load.x", "m", name)
    export = export_fmu(system, tmp_path, binary=False, name="spring")
    root = _description(export.path)
    assert root.get("modelName") == xml_text(name) and root.get("description") == xml_text(name)
    (y,) = [v for v in _variables(root) if v.get("name") == "y"]
    assert y.get("description") == xml_text(name)
    with zipfile.ZipFile(export.path) as archive:
        sources = {n: archive.read(n).decode() for n in archive.namelist() if n.endswith((".c", ".h"))}
    heads = [t.split("\n", 1)[0] for t in sources.values() if t.startswith("/*") and "hydroservo model '" in t]
    assert heads  # the stepper's and the FMI interface's
    for first in heads:
        quoted = first.split("'", 1)[1].rsplit("'", 1)[0]  # the name, escaped: one line, no comment end
        assert "*/" not in quoted and "@" not in quoted.replace("@NAME@", "") and quoted.isascii()
