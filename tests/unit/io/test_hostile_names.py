"""Names, descriptions and paths that reach a file we write cannot change what the file says (issue 37).

Every writer of a format puts text through one escaper of that format (io.text.one_line for comments, io.toml
for TOML strings, keys and comments, io.results for CSV headers and comments, io.text.xml_text for an FMU's XML,
io.html's script JSON), and what import-hopsan and export write is read back as the same model before it is
written. Each case here is a hostile name: a line break that would start a TOML table, a carriage return, control
characters, quotes, backslashes, ``#``, ``[``, triple quotes, U+2028, a Python keyword, 10,000 characters.
"""

from __future__ import annotations

import csv
import io
import json
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path
from xml.sax.saxutils import quoteattr

import pytest

from hydroservo.components.base import MAX_NAME, name_problem
from hydroservo.errors import ModelFileError, ParameterError
from hydroservo.io.model_file import load_model, model_to_toml, read_model
from hydroservo.io.results import csv_comments, csv_header_row, write_table
from hydroservo.io.text import comment_lines, one_line, xml_text
from hydroservo.io.toml import toml_comment, toml_key, toml_string

#: The injection of the issue: a name whose lines after the break are live TOML (the mass starts at 0.5 m)
INJECTION = 'Force\n[initial]\n"Mass.x" = "0.5 m"\n#'
HOSTILE = {
    "injection": INJECTION,
    "carriage-return": 'cr\r[initial]\r"Mass.x" = "0.5 m"',
    "control": "nul\x00esc\x1bdel\x7fbell\x07",
    "quotes-backslashes": 'quote " back\\slash \\" \\\\',
    "hash-bracket": "hash # [section] ]]",
    "triple-quotes": "triple \"\"\" and ''' inside",
    "line-separators": "line\u2028sep\u2029para\x85next",
    "keyword": "class",
    "long": "L" * 10_000,
}
#: What an XML attribute can hold (an .hmf is XML 1.0: no NUL or other control characters, even as references)
XML_HOSTILE = {k: v for k, v in HOSTILE.items() if k != "control"}


@pytest.mark.parametrize("text", list(HOSTILE.values()), ids=list(HOSTILE))
def test_toml_strings_keys_and_comments_hold_any_text(text: str) -> None:
    doc = f"{toml_comment(text)}\n{toml_key(text)} = {toml_string(text)}  {toml_comment(text)}\n"
    assert tomllib.loads(doc) == {text: text}  # the comments are comments, the value is the text
    assert doc.count("\n") == 2 and doc.isprintable() is False  # two lines: nothing in the text broke one
    assert all(line.isprintable() for line in doc.splitlines())  # U+2028 and the like escaped too


@pytest.mark.parametrize("text", list(HOSTILE.values()), ids=list(HOSTILE))
def test_comment_lines_are_lines_of_comments(text: str) -> None:
    assert "\n" not in one_line(text) and one_line(text).isprintable()
    lines = comment_lines(f"head\n{text}\ntail")
    assert all(line.startswith("#") and line.isprintable() for line in lines)
    assert tomllib.loads("\n".join(lines)) == {}


def test_a_lone_surrogate_is_refused_as_a_toml_string() -> None:
    with pytest.raises(ParameterError, match="lone surrogate"):
        toml_string("a\ud800b")
    assert one_line("a\ud800b") == "a\\ud800b"


@pytest.mark.parametrize("text", list(HOSTILE.values()), ids=list(HOSTILE))
def test_csv_headers_and_comments_stay_on_their_lines(text: str, tmp_path: Path) -> None:
    path = write_table(tmp_path / "t.csv", ["t [s]", f"{text} [m]"], [[0.0, 1.0], [1.0, 2.0]], [text, "second"])
    body = path.read_text(encoding="utf-8-sig")
    comments = [line for line in body.splitlines() if line.startswith("#")]
    assert len(comments) == len(comment_lines(text)) + 1  # every line of the comment is a comment
    rows = list(csv.reader(io.StringIO("".join(line + "\n" for line in body.splitlines() if not line.startswith("#")))))
    assert rows[0] == ["t [s]", f"{one_line(text)} [m]"] and rows[1:] == [["0.0", "1.0"], ["1.0", "2.0"]]
    assert csv_header_row(["a,b", 'c"d']) == '"a,b","c""d"\n' and csv_comments(["x\ny"]) == "# x\n# y\n"


@pytest.mark.parametrize("text", list(HOSTILE.values()), ids=list(HOSTILE))
def test_xml_text_is_what_an_xml_document_holds(text: str) -> None:
    root = ET.fromstring(ET.tostring(ET.Element("m", name=xml_text(text))))
    assert root.get("name") == xml_text(text)  # read back as written: line breaks and quotes escaped by the writer
    if text in XML_HOSTILE.values():
        assert xml_text(text) == text  # what XML holds is kept as it is
    else:
        assert xml_text(text) == "nul\\x00esc\\x1bdel\x7fbell\\x07"  # what it cannot hold, as its escape


def test_script_json_in_a_report_has_no_tag_to_end_it() -> None:
    from hydroservo.io.html import _script_json

    value = {"name": "</script><!--<script>alert(1)", "sep": "\u2028"}
    text = _script_json(value)
    assert "<" not in text and "\u2028" not in text and json.loads(text) == value


@pytest.mark.parametrize("text", list(HOSTILE.values()), ids=list(HOSTILE))
def test_write_model_of_a_system_named_anything_reads_back(text: str, tmp_path: Path) -> None:
    from hydroservo.io.model_file import write_model

    system = load_model("position-servo")
    system.name, system.description = text, text
    system.alias("hostile", "-load.x", "m", text)
    again = read_model(write_model(system, tmp_path / "m.toml"))
    assert (again.name, again.description, again.aliases["hostile"].description) == (text, text, text)
    assert again.initial == system.initial and again.parameter_values() == system.parameter_values()


def test_the_component_name_rule_refuses_keywords_and_long_names_at_loading(tmp_path: Path) -> None:
    assert name_problem("class") and name_problem("x" * (MAX_NAME + 1)) and name_problem("4x")
    assert name_problem("match") is None and name_problem("x" * MAX_NAME) is None  # soft keywords are names
    text = model_to_toml(load_model("position-servo"))
    for bad, why in (("class", "keyword"), ("L" * 10_000, "10000 characters")):
        path = tmp_path / "m.toml"
        path.write_text(text.replace("[components.load]", f"[components.{bad}]"), encoding="utf-8")
        with pytest.raises(ModelFileError, match=why):  # refused when read, not when first simulated
            read_model(path)


@pytest.mark.parametrize("text", list(HOSTILE.values()), ids=list(HOSTILE))
@pytest.mark.parametrize("full", [False, True], ids=["plain", "full"])
def test_export_of_a_model_named_anything_loads_as_the_same_model(text: str, full: bool, tmp_path: Path) -> None:
    from hydroservo.workflows.export import model_file

    system = load_model("position-servo")
    system.name, system.description, system.notes = text, text, [text]
    path = tmp_path / "hostile.toml"
    path.write_text(model_to_toml(system), encoding="utf-8")
    original = read_model(path)
    assert original.name == text
    out = tmp_path / "exported.toml"
    out.write_text(model_file(path, full=full).text, encoding="utf-8")
    again = read_model(out)
    assert again.name == text and again.description == text
    assert again.initial == original.initial and "load.x" not in again.initial
    assert again.parameter_values() == original.parameter_values()


# -- import-hopsan ---------------------------------------------------------------------------------------------


def _attr(text: str) -> str:
    return quoteattr(text, {"\n": "&#10;", "\r": "&#13;", "\t": "&#9;"})


def _hmf(force: str = "Force", mass: str = "Mass") -> str:
    """A force on a mass on a spring to a wall, as Hopsan writes it, with the force and mass named as given."""
    comps = [
        ("MechanicForceTransformer", force, {"F#Value": ("10", "N")}),
        ("MechanicTranslationalMass", mass, {"m": ("1", "kg"), "B#Value": ("1", "Ns/m"), "k#Value": ("0", "N/m"),
                                             "x_min#Value": ("-1", "m"), "x_max#Value": ("1", "m")}),
        ("MechanicTranslationalSpring", "Spring", {"k#Value": ("100", "N/m")}),
        ("MechanicFixedPosition", "Wall", {"m_e": ("1", "kg")}),
    ]
    links = [((force, "P1"), (mass, "P1")), ((mass, "P2"), ("Spring", "P1")), (("Spring", "P2"), ("Wall", "Pm1"))]
    objects = "".join(
        f'<component name={_attr(name)} typename="{kind}" cqstype="S"><parameters>'
        + "".join(f'<parameter type="double" name="{k}" value="{v}" unit="{u}"/>' for k, (v, u) in params.items())
        + "</parameters></component>"
        for kind, name, params in comps
    )
    connects = "".join(
        f"<connect startcomponent={_attr(a)} startport={_attr(pa)} endcomponent={_attr(b)} endport={_attr(pb)}/>"
        for (a, pa), (b, pb) in links
    )
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n<hopsanmodelfile hmfversion="0.4"><system name="Small" '
        'typename="Subsystem"><simulationtime stop="1" timestep="0.001" start="0"/>'
        f"<objects>{objects}</objects><connections>{connects}</connections></system></hopsanmodelfile>"
    )


def _import_and_reload(hmf: Path, out: Path):
    import warnings

    from hydroservo.workflows.hopsan import ImportHopsan

    report = ImportHopsan(hmf).run()
    written = Path(report.write(out)["model"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        again = read_model(written)
    return report, written, again


def _assert_same_model(report, written: Path, again) -> None:
    from hydroservo.system.expressions import names_in

    system = report.imported.system
    assert list(again.components) == list(system.components)
    assert again.initial == system.initial and "Mass.x" not in again.initial  # nothing started the mass
    assert again.parameter_values() == system.parameter_values()
    for name, alias in again.aliases.items():  # every expression can be read: the model runs
        names_in(alias.expr, name)
    lines = written.read_text(encoding="utf-8").splitlines()
    assert all(line.isprintable() for line in lines)


@pytest.mark.parametrize("name", list(XML_HOSTILE.values()), ids=list(XML_HOSTILE))
@pytest.mark.parametrize("which", ["force", "mass"])
def test_import_hopsan_of_components_named_anything_writes_the_model_imported(name: str, which: str, tmp_path: Path) -> None:
    hmf = tmp_path / "small.hmf"
    hmf.write_text(_hmf(**{which: name}), encoding="utf-8")
    report, written, again = _import_and_reload(hmf, tmp_path / "out")
    _assert_same_model(report, written, again)
    text = written.read_text(encoding="utf-8")
    assert not any(line.startswith("[initial]") for line in text.splitlines())
    if name in ("class", "L" * 10_000):  # renamed to what the model file's rule takes, and said so
        new = report.imported.names[name]
        assert name_problem(new) is None and report.imported.renamed == {name: new}
        assert "renamed" in "\n".join(report.lines()) and f"-> {new}" in text


@pytest.mark.parametrize(
    "stem",
    ['bad\nname', 'cr\rname', 'class', 'quote"#[x]', "triple'''", "sep\u2028x", "n" * 200],
    ids=["newline", "cr", "keyword", "quote-hash-bracket", "triple-quotes", "u2028", "long"],
)
def test_import_hopsan_of_a_file_named_anything_writes_a_file_that_loads(stem: str, tmp_path: Path) -> None:
    hmf = tmp_path / f"{stem}.hmf"
    hmf.write_text(_hmf(), encoding="utf-8")
    report, written, again = _import_and_reload(hmf, tmp_path / "out")
    _assert_same_model(report, written, again)
    assert written.suffix == ".toml" and written.name.isprintable() and written.parent == tmp_path / "out"


def test_an_hmf_without_components_is_refused_before_anything_is_written(tmp_path: Path) -> None:
    from hydroservo.workflows.hopsan import ImportHopsan

    hmf = tmp_path / "empty.hmf"
    hmf.write_text(
        '<?xml version="1.0"?><hopsanmodelfile><system name="x"><simulationtime stop="1" timestep="0.001" '
        'start="0"/><objects/></system></hopsanmodelfile>',
        encoding="utf-8",
    )
    with pytest.raises(ModelFileError, match=r"empty\.hmf: no components; expected a Hopsan model with at least one"):
        ImportHopsan(hmf)
    sinks = hmf.with_name("sinks.hmf")
    sinks.write_text(_hmf().replace("MechanicForceTransformer", "SignalSink").split("<objects>")[0]
                     + '<objects><component name="Sink" typename="SignalSink"/></objects></system></hopsanmodelfile>',
                     encoding="utf-8")
    with pytest.raises(ModelFileError, match="no component hydroservo keeps"):
        ImportHopsan(sinks)
