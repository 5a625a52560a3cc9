"""Every published law documents what it takes, what it gives and where it comes from.

After python-control's ``test_docstrings.py``: for every public function of
every module of :mod:`hydroservo.laws` (the functions in the module's
``__all__``), the numpydoc docstring must have

* a ``Parameters`` section that documents every parameter of the signature,
  and nothing else, each with its unit in square brackets in its description
  (``[Pa]``, ``[m^3/s]``, ``[degC]``; ``[-]`` for a dimensionless one);
* a ``Returns`` section;
* a ``References`` section citing at least one key of
  :mod:`hydroservo.references` in brackets, ``[Efe2014]``.

And every citation key in brackets anywhere in the package's sources must be a
key of the bibliography.
"""

from __future__ import annotations

import inspect
import re
from pathlib import Path

import pytest

import hydroservo
from hydroservo import laws, references

KEYS = set(references.keys())

#: A key-like citation in brackets: AuthorYear, AuthorND, or a standard (SAEARP490, ISO3448).
CITATION = re.compile(r"\[([A-Z][A-Za-z]*(?:[0-9]{4}|ND|[A-Z]{3}[0-9]+|[A-Z]{2,4}[0-9]{3,4}))\]")

#: Anything in square brackets that is not a citation key and not a numeric interval such as [-1, 1].
INTERVAL = re.compile(r"^\s*[-+]?[0-9.]+(e[-+]?[0-9]+)?\s*,")


def _law_functions() -> list[tuple[str, object]]:
    out = []
    for modname in laws.__all__:
        module = getattr(laws, modname)
        for name in module.__all__:
            obj = getattr(module, name)
            if inspect.isfunction(obj):
                out.append((f"{modname}.{name}", obj))
    return out


LAWS = _law_functions()


def _sections(doc: str) -> dict[str, list[str]]:
    """numpydoc sections: title -> its lines (a title is a line underlined by dashes of its length)."""
    lines = doc.splitlines()
    out: dict[str, list[str]] = {}
    current = None
    i = 0
    while i < len(lines):
        line = lines[i]
        title = line.strip()
        underline = lines[i + 1].strip() if i + 1 < len(lines) else ""
        if title and not line.startswith(" ") and underline == "-" * len(title):
            current = title
            out[current] = []
            i += 2
            continue
        if current is not None:
            out[current].append(line)
        i += 1
    return out


def _parameters(lines: list[str]) -> list[tuple[list[str], str]]:
    """Entries of a Parameters section: (names, description); ``a, b : float`` documents a and b."""
    entries: list[tuple[list[str], str]] = []
    for line in lines:
        if not line.strip():
            continue
        if not line.startswith(" "):
            names = [n.strip() for n in line.split(" : ")[0].split(",")]
            entries.append((names, ""))
        elif entries:
            names, text = entries[-1]
            entries[-1] = (names, f"{text} {line.strip()}")
    return entries


def _units(text: str) -> list[str]:
    return [
        u
        for u in re.findall(r"\[([^\[\]]+)\]", text)
        if u not in KEYS and not INTERVAL.match(u) and not CITATION.fullmatch(f"[{u}]")
    ]


def test_laws_found():
    assert len(LAWS) > 40
    assert {"fluid.bulk_modulus_lee", "leakage.ellman_flow", "staged_slot.slot_flow"} <= {n for n, _ in LAWS}


@pytest.mark.parametrize("name, func", LAWS, ids=[n for n, _ in LAWS])
def test_parameters_documented_with_units(name, func):
    doc = inspect.getdoc(func)
    assert doc, f"{name}: no docstring"
    sections = _sections(doc)
    assert "Parameters" in sections, f"{name}: no Parameters section"
    entries = _parameters(sections["Parameters"])
    documented = [n for names, _ in entries for n in names]
    expected = [p.name for p in inspect.signature(func).parameters.values()]
    missing = [p for p in expected if p not in documented]
    extra = [p for p in documented if p not in expected]
    assert not missing, f"{name}: parameters not documented: {missing}"
    assert not extra, f"{name}: documented but not in the signature: {extra}"
    assert len(documented) == len(set(documented)), f"{name}: a parameter documented twice"
    no_unit = [", ".join(names) for names, text in entries if not _units(text)]
    assert not no_unit, f"{name}: no unit in [brackets] in the description of {no_unit}"


@pytest.mark.parametrize("name, func", LAWS, ids=[n for n, _ in LAWS])
def test_returns_documented(name, func):
    sections = _sections(inspect.getdoc(func) or "")
    assert "Returns" in sections, f"{name}: no Returns section"
    assert any(line.strip() for line in sections["Returns"]), f"{name}: empty Returns section"


@pytest.mark.parametrize("name, func", LAWS, ids=[n for n, _ in LAWS])
def test_references_cite_a_key(name, func):
    sections = _sections(inspect.getdoc(func) or "")
    assert "References" in sections, f"{name}: no References section"
    cited = set(CITATION.findall(" ".join(sections["References"])))
    assert cited & KEYS, f"{name}: References cite no key of hydroservo.references in [brackets]"


def test_every_cited_key_is_in_the_bibliography():
    root = Path(hydroservo.__file__).parent
    unknown = {}
    for path in sorted(root.rglob("*.py")):
        for key in CITATION.findall(path.read_text(encoding="utf-8")):
            if key not in KEYS:
                unknown.setdefault(key, []).append(str(path.relative_to(root)))
    assert not unknown, f"citation keys not in references.bib: {unknown}"


def test_section_parser():
    doc = inspect.cleandoc(
        """Title.

        Parameters
        ----------
        a, b : float
            Lengths [m].
        c : float
            In [-1, 1], see [Efe2014].

        Returns
        -------
        float
            [m].
        """
    )
    sections = _sections(doc)
    assert set(sections) == {"Parameters", "Returns"}
    entries = _parameters(sections["Parameters"])
    assert [names for names, _ in entries] == [["a", "b"], ["c"]]
    assert _units(entries[0][1]) == ["m"]
    assert _units(entries[1][1]) == []
