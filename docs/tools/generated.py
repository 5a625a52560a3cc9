"""The generated parts of the docs: the component reference and glossary from the component registry, validation
tables from the rows.

Run: ``python docs/tools/generated.py`` rewrites the parts of ``docs/components.md``,
``docs/nomenclature.md`` and ``docs/validation.md`` between
``<!-- generated: NAME -->`` and ``<!-- end generated: NAME -->``; a test fails
when a doc differs from what this would write, so the docs and the code are
one source.
"""

from __future__ import annotations

import re
import sys
from collections import defaultdict
from pathlib import Path

from hydroservo.components import REGISTRY
from hydroservo.components.reference import catalogue
from hydroservo.components.reference import markdown as component_markdown
from hydroservo.units import si_unit
from hydroservo.validation import VALIDATIONS, markdown, validate

DOCS = Path(__file__).resolve().parents[1]


def glossary() -> str:
    """Every parameter name of every component: unit, meaning, components."""
    rows: dict[str, dict[str, object]] = {}
    users: dict[str, list[str]] = defaultdict(list)
    for cname, cls in sorted(REGISTRY.types.items()):
        for key, spec in cls.PARAMETERS.items():
            users[key].append(cname)
            rows.setdefault(key, {"unit": spec.unit, "meaning": spec.description})
    lines = ["| parameter | unit | meaning | components |", "|---|---|---|---|"]
    for key in sorted(rows, key=str.lower):
        unit = str(rows[key]["unit"])
        shown = "signal's unit" if "@" in unit else si_unit(unit)
        lines.append(f"| `{key}` | {shown} | {rows[key]['meaning']} | {', '.join(users[key])} |")
    return "\n".join(lines)


def renamed() -> str:
    """Parameters and component types renamed, with their former names (still accepted, with a warning)."""
    lines = ["| component | former name | name |", "|---|---|---|"]
    for cname, cls in sorted(REGISTRY.types.items()):
        for old, new in sorted(cls.RENAMED.items()):
            lines.append(f"| {cname} | `{old}` | `{new}` |")
    for old, new in sorted(REGISTRY.renamed.items()):
        lines.append(f"| (component type) | `{old}` | `{new}` |")
    return "\n".join(lines)


def component_reference() -> dict[str, str]:
    """Every component type, by kind: its notes, parameters, options, signals and limits."""
    sections: list[str] = []
    kind = None
    for ref in catalogue():
        group = ref.kind.split(".")[0]
        if group != kind:
            sections.append(f"## {group}\n")
            kind = group
        sections.append(component_markdown(ref))
    return {"components": "\n".join(sections).rstrip()}


def validation_tables() -> dict[str, str]:
    return {f"validation-{name}": markdown(validate(name)) for name in VALIDATIONS}


def parts() -> dict[str, str]:
    return {"glossary": glossary(), "renamed": renamed()}


def fill(text: str, blocks: dict[str, str]) -> str:
    """``text`` with every generated block replaced by its current content."""
    for name, body in blocks.items():
        start, end = f"<!-- generated: {name} -->", f"<!-- end generated: {name} -->"
        pattern = re.compile(re.escape(start) + r".*?" + re.escape(end), re.S)
        if not pattern.search(text):
            raise KeyError(f"no generated block {name!r}")
        block = f"{start}\n{body}\n{end}"
        text = pattern.sub(lambda m, block=block: block, text)
    return text


def main() -> None:
    documents = (
        ("components.md", component_reference()),
        ("nomenclature.md", parts()),
        ("validation.md", validation_tables()),
    )
    for doc, blocks in documents:
        path = DOCS / doc
        path.write_text(fill(path.read_text(encoding="utf-8"), blocks), encoding="utf-8")
        print(path)


if __name__ == "__main__":
    sys.exit(main())
