"""The bibliography: every source hydroservo cites, by its AuthorYear key.

Docstrings cite a key in brackets with the equation, ``[FerreiraND] eq. (24)``;
parameter sets (:mod:`hydroservo.data`), built-in models and validation rows
name theirs. The entries are ``references.bib`` in the package, BibTeX.

>>> from hydroservo import references
>>> references.entry("Efe2014")["year"]
'2014'
"""

from __future__ import annotations

import functools
import re
from importlib import resources

__all__ = ["entries", "entry", "keys", "cite", "cited_in"]


@functools.cache
def entries() -> dict[str, dict[str, str]]:
    """Every entry of ``references.bib``: key -> fields (``entrytype`` is the BibTeX entry type)."""
    text = resources.files("hydroservo").joinpath("references.bib").read_text(encoding="utf-8")
    out: dict[str, dict[str, str]] = {}
    for match in re.finditer(r"@(\w+)\{([^,\s]+),(.*?)\n\}", text, flags=re.S):
        kind, key, body = match.groups()
        fields = {"entrytype": kind.lower()}
        for f in re.finditer(r"(\w+)\s*=\s*\{(.*?)\},?\s*$", body, flags=re.M | re.S):
            fields[f.group(1).lower()] = " ".join(f.group(2).split())
        out[key] = fields
    return out


def keys() -> list[str]:
    """The citation keys."""
    return list(entries())


def entry(key: str) -> dict[str, str]:
    """The fields of entry ``key``."""
    try:
        return entries()[key]
    except KeyError:
        raise KeyError(f"no reference {key!r}; keys: {', '.join(entries())}") from None


def cite(key: str) -> str:
    """A one-line citation: authors (year). Title. Where — the parts the entry has.

    >>> cite("Efe2014")
    'Efe, Yalcin (2014). Dynamic Model of a Hydraulic Servo System for a Manipulator Robot. KTH Royal Institute of Technology.'
    """
    e = entry(key)
    authors = e.get("author", "Anonymous").replace(" and ", "; ").replace("{", "").replace("}", "")
    where = e.get("journal") or e.get("booktitle") or e.get("school") or e.get("publisher") or e.get("type")
    parts = [f"{authors} ({e.get('year', 'n.d.')})", e.get("title"), where]
    return ". ".join(p.rstrip(".") for p in parts if p) + "."


def cited_in(text: str) -> list[str]:
    """The keys of the bibliography a text cites in brackets, in the order they first appear: ``[Efe2014]``
    followed by an equation, ``[GordicND, Table 1]``.

    >>> cited_in("the flow of [Efe2014] eq. 3.5, after [Merritt1967] and [Efe2014]; not [Fig3]")
    ['Efe2014', 'Merritt1967']
    """
    known = entries()
    found: list[str] = []
    for match in re.finditer(r"\[([A-Za-z][A-Za-z0-9]*)[\],;]", text):
        key = match.group(1)
        if key in known and key not in found:
            found.append(key)
    return found
