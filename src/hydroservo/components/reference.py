"""The component reference: every component's equations, parameters, ports and options, from its declarations.

``hydroservo components`` lists the types, ``hydroservo describe TYPE`` prints
one, and docs/components.md is generated from the same :func:`reference`, so
the reference cannot drift from the code.
"""

from __future__ import annotations

import functools
import inspect
import re
from dataclasses import asdict, dataclass, field, replace
from typing import Any

from hydroservo.components.base import REGISTRY, SIGNAL, Component, FromSet
from hydroservo.errors import ParameterError, did_you_mean
from hydroservo.references import cited_in, keys
from hydroservo.units import si_unit

__all__ = ["Reference", "reference", "catalogue", "text", "markdown", "citations"]

#: Constructor arguments that are not parameters, and what they are.
_ARGUMENTS = {
    "unit": "the unit of the signal the block passes on (its parameters marked 'signal' take it)",
    "tables": "tables of the flow coefficient and hysteresis against spool position (see the class notes)",
    "times": "times of the table [s]",
    "pressures": "pressures of the table [Pa]",
    "values": "values of the table, in the block's unit",
    "source": "the CSV file a model file read the table from (written back on export)",
    "input_unit": "the unit of the signal the block takes (its gain is then in unit/input_unit)",
    "segments": "number of lumped segments, or 'auto': the fewest that carry waves up to f_max",
    "ends": "what each end is: 'pressure', 'flow', 'pressure-flow' or 'flow-pressure' (which ports it joins)",
    "pistons": "number of pistons (each its own port, numbered from 1)",
}


@dataclass
class Reference:
    """What a component type declares, in plain values (``asdict`` gives JSON)."""

    name: str
    kind: str  #: its module under hydroservo.components, e.g. "valves.four_way"
    summary: str  #: the first sentence of its docstring
    notes: str  #: the docstring: equations (in Unicode), sources, conventions
    source: str = ""  #: the docstring as written (reStructuredText, equations in LaTeX)
    arguments: dict[str, str] = field(default_factory=dict)
    parameters: list[dict[str, Any]] = field(default_factory=list)
    options: list[dict[str, Any]] = field(default_factory=list)
    states: list[dict[str, Any]] = field(default_factory=list)
    inputs: list[dict[str, Any]] = field(default_factory=list)
    outputs: list[dict[str, Any]] = field(default_factory=list)
    hydraulic: list[dict[str, Any]] = field(default_factory=list)
    limits: list[dict[str, Any]] = field(default_factory=list)
    renamed: dict[str, str] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def _unit(unit: str) -> str:
    if SIGNAL in unit:
        unit = unit.replace(SIGNAL + "in", "input")  # a gain's input unit
        return unit.replace(SIGNAL, "signal") if unit != SIGNAL else "signal"
    return si_unit(unit)


_ROLE = re.compile(r":(?:class|func|mod|meth|attr|data):`~?(?:[\w.]+\.)?([\w]+)`")
_MATH_ROLE = re.compile(r":math:`([^`]*)`")


def _math_blocks(doc: str) -> list[tuple[str, str]]:
    """``doc`` cut into prose and math directives' blocks: (kind, text) with kind "text" or "math" (LaTeX, its
    lines joined, the block's indentation removed)."""
    parts: list[tuple[str, str]] = []
    lines, k = doc.splitlines(), 0
    prose: list[str] = []
    while k < len(lines):
        line = lines[k]
        found = re.match(r"(\s*)\.\. math::\s*(.*)$", line)
        if not found:
            prose.append(line)
            k += 1
            continue
        if prose:
            parts.append(("text", "\n".join(prose)))
            prose = []
        indent = len(found.group(1))
        body = [found.group(2)] if found.group(2).strip() else []
        k += 1
        while k < len(lines) and (not lines[k].strip() or len(lines[k]) - len(lines[k].lstrip()) > indent):
            body.append(lines[k].strip())
            k += 1
        parts.append(("math", "\n".join(b for b in body if b)))
    if prose:
        parts.append(("text", "\n".join(prose)))
    return parts


@functools.cache
def _latex_to_text() -> Any:
    """pylatexenc's LaTeX-to-Unicode converter, with fractions grouped as ``(a + b)/(c d)``, ``\\sin`` spaced, and
    the layout macros (``\\qquad``, ``\\left``, ``\\right``) reduced to spacing."""
    from pylatexenc.latex2text import LatexNodes2Text, MacroTextSpec, get_default_latex_context_db

    def group(text: str) -> str:
        text = text.strip()
        return text if re.fullmatch(r"[\w.'′]+(\([^()]*\))?|\([^()]*\)", text) else f"({text})"

    def frac(node: Any, l2tobj: Any) -> str:
        top, bottom = (l2tobj.nodelist_to_text([arg]) for arg in node.nodeargd.argnlist[-2:])
        return f"{group(top)}/{group(bottom)}"

    db = get_default_latex_context_db().filter_context(keep_categories=None)
    macros = [MacroTextSpec("frac", simplify_repl=frac), MacroTextSpec("dfrac", simplify_repl=frac),
              MacroTextSpec("qquad", "    "), MacroTextSpec("quad", "  "), MacroTextSpec("left", ""),
              MacroTextSpec("right", ""), MacroTextSpec("mathrm", "%s"), MacroTextSpec("text", "%s")]
    macros += [MacroTextSpec(f, f"{f} ") for f in ("sin", "cos", "tan", "cot", "tanh", "exp", "ln", "log", "max", "min", "sign")]
    db.add_context_category("hydroservo", macros=macros, prepend=True)
    return LatexNodes2Text(math_mode="text", latex_context=db, strict_latex_spaces="based-on-source")


def _group_end(text: str, k: int) -> int:
    """The index after the brace group that starts at ``text[k]`` (``{``), or after the one character there."""
    if k >= len(text) or text[k] != "{":
        return k + 1
    depth = 0
    for j in range(k, len(text)):
        depth += {"{": 1, "}": -1}.get(text[j], 0)
        if depth == 0:
            return j + 1
    return len(text)


def _readable(latex: str) -> str:
    r"""LaTeX made unambiguous as plain text before it is rendered: a fraction that a factor follows is put in
    brackets (``[a/b](c + d)``, not ``a/b(c + d)``), a symbol after a symbol gets a space (``A_A ẋ``, not
    ``A_Aẋ``), a third derivative is primed (``x‴``)."""
    latex = re.sub(r"\\dddot\s*(\{[^{}]*\}|[A-Za-z])", lambda m: m.group(1).strip("{}") + "‴", latex)
    out, k = [], 0
    while k < len(latex):
        if latex.startswith("\\frac", k) or latex.startswith("\\dfrac", k):
            start = k
            k = latex.index("frac", k) + 4
            for _ in range(2):  # numerator, denominator
                while k < len(latex) and latex[k] == " ":
                    k += 1
                k = _group_end(latex, k)
            inner = latex[start:k]
            head = inner.index("frac") + 4
            frac = inner[:head] + _readable(inner[head:])  # fractions inside fractions
            rest = re.sub(r"^(\s|\\,)+", "", latex[k:])
            factor = bool(re.match(r"[\w(\[{]|\\(?!\\|,|quad|qquad|right|end)", rest))
            out.append(f"[{frac}]" if factor else frac)
            continue
        out.append(latex[k])
        k += 1
    spaced = re.sub(r"(?<=[\w}'])\s*\\(?=(?!right|end|quad|qquad)[A-Za-z])", r" \\", "".join(out))
    return spaced


def equation_text(latex: str) -> str:
    """LaTeX as a terminal shows it: Greek letters, dots and roots in Unicode, fractions as ``a/(b c)``, one line
    per line of an aligned block.

    >>> equation_text(r"\\dot p = \\frac{Q}{C(p)}, \\qquad C(p) = \\frac{V_{dead}}{\\beta_e} + \\frac{V_g}{\\kappa\\,p_{abs}}")
    'ṗ = Q/C(p),      C(p) = V_dead/β_e + V_g/(κ p_abs)'
    """
    lines = [_readable(line.replace("&", "").replace("\n", " ")) for line in re.split(r"\\\\", latex)]
    shown = [" ".join(_latex_to_text().latex_to_text(line).split(" \n")).strip() for line in lines]
    return "\n".join(line for line in shown if line)


def plain(doc: str) -> str:
    """A docstring for a terminal: its roles reduced to names in backquotes, its equations in Unicode
    (:func:`equation_text`; the math directive's blocks indented under the prose, the math role's inline)."""
    out = []
    for kind, part in _math_blocks(doc):
        if kind == "math":
            out.append("\n".join("    " + line for line in equation_text(part).splitlines()) + "\n")
            continue
        part = _ROLE.sub(r"`\1`", part)
        part = _MATH_ROLE.sub(lambda m: equation_text(m.group(1)), part)
        out.append(part.replace("``", "`"))
    return "\n".join(out)


def markdown_prose(doc: str) -> str:
    """A docstring for MyST Markdown: equations as ``$$`` blocks and ``$...$``, roles as names in backquotes."""
    out = []
    for kind, part in _math_blocks(doc):
        if kind == "math":
            body = part.replace("\n", " ")
            aligned = "&" in body or "\\\\" in body
            out += ["", "$$", f"\\begin{{aligned}}{body}\\end{{aligned}}" if aligned else body, "$$", ""]
            continue
        part = _ROLE.sub(r"`\1`", part)
        part = _MATH_ROLE.sub(lambda m: f"${m.group(1)}$", part)
        out.append(part.replace("``", "`"))
    return "\n".join(out)


def _declarations(cls: type[Component]) -> Any:
    """What a component declares: the class, or for one whose ports and states depend on its arguments (a
    line's segments) an instance with the default arguments."""
    if cls.STATES or cls.INPUTS or cls.OUTPUTS:
        return cls
    try:
        return cls("example")
    except Exception:  # noqa: BLE001 - a type that needs arguments: its class declarations
        return cls


def reference(type_name: str | type[Component]) -> Reference:
    """The reference of a component type, by class or registered name (former names accepted)."""
    if isinstance(type_name, str):
        cls = REGISTRY.resolve(type_name)
        if cls is None:
            from hydroservo.data import model_names

            if type_name in model_names():
                raise ParameterError(
                    f"{type_name!r} is a built-in model, not a component type: `hydroservo simulate {type_name}` runs "
                    f"it, `hydroservo draw {type_name}` draws its circuit; component types: "
                    f"{', '.join(sorted(REGISTRY.types))}"
                )
            raise ParameterError(
                f"component type {type_name!r}: unknown{did_you_mean(type_name, REGISTRY.types)}; known: "
                f"{', '.join(sorted(REGISTRY.types))}"
            )
    else:
        cls = type_name
    declared = _declarations(cls)
    doc = inspect.getdoc(cls) or ""
    summary = plain(doc.split("\n\n")[0]).replace("\n", " ")
    signature = inspect.signature(cls.__init__)
    variadic = (inspect.Parameter.VAR_KEYWORD, inspect.Parameter.VAR_POSITIONAL)
    arguments = {
        k: _ARGUMENTS.get(k, "") for k, p in signature.parameters.items() if k not in ("self", "name") and p.kind not in variadic
    }
    groups = (cls.PARAMETERS, declared.INPUTS, declared.OUTPUTS, declared.STATES)
    uses_signal = any(SIGNAL in spec.unit for group in groups for spec in group.values())
    if not uses_signal:
        arguments.pop("unit", None)
    parameters = []
    for key, spec in cls.PARAMETERS.items():
        default: Any = spec.default
        bounds = replace(spec, unit="").expected()  # the unit has its own column
        meaning = spec.description
        if spec.fluid:
            meaning += f"; in a system with a fluid, the fluid's {spec.fluid.replace('_', ' ')} unless set here"
        entry: dict[str, Any] = {"name": key, "unit": _unit(spec.unit), "description": meaning, "range": bounds}
        if isinstance(default, FromSet):
            entry["default"] = spec.si_default()
            entry["default_from"] = f"{default.set_name} [{default.table}] {default.key}"
        else:
            entry["default"] = float(default)
        parameters.append(entry)
    return Reference(
        name=cls.__name__,
        kind=cls.__module__.removeprefix("hydroservo.components."),
        summary=summary,
        notes=plain(doc),
        source=doc,
        arguments=arguments,
        parameters=parameters,
        options=[
            {"name": k, "default": o.default, "choices": list(o.choices), "description": o.description}
            for k, o in cls.OPTIONS.items()
        ],
        states=[
            {"name": k, "unit": _unit(s.unit), "description": s.description, "initial": s.initial}
            for k, s in declared.STATES.items()
        ],
        inputs=[
            {"name": k, "unit": _unit(p.unit), "description": p.description, "default": p.default}
            for k, p in declared.INPUTS.items()
        ],
        outputs=[{"name": k, "unit": _unit(o.unit), "description": o.description} for k, o in declared.OUTPUTS.items()],
        hydraulic=[
            {
                "name": k,
                "kind": "pressure" if h.p in declared.OUTPUTS else "flow",
                "p": h.p,
                "Q": h.Q,
                "Q_positive": "into the component" if h.into else "out of the component",
                "description": h.description,
            }
            for k, h in declared.HYDRAULIC.items()
        ],
        limits=[
            {"signal": k, "kind": lim.kind, "lower": lim.lower, "upper": lim.upper} for k, lim in declared.LIMITS.items()
        ],
        renamed=dict(cls.RENAMED),
    )


def citations(component: type[Component] | Component) -> list[str]:
    """The bibliography entries a component stands on by itself, in the bibliography's order: those the first
    paragraph of its docstring (what it is and where it comes from) cites, and, for a component, the sources
    of the parameter sets its defaults come from where it keeps them. The laws its equations call cite their
    own (:meth:`hydroservo.system.System.references` collects those a system's assembly calls).

    >>> citations(REGISTRY.resolve("TwoStageServovalve"))
    ['GordicND']
    """
    cls = component if isinstance(component, type) else type(component)
    found = cited_in((inspect.getdoc(cls) or "").split("\n\n")[0])
    if not isinstance(component, type):
        from hydroservo.data import parameter_set

        for key, spec in cls.PARAMETERS.items():
            if isinstance(spec.default, FromSet) and key not in component.explicit:
                found.append(parameter_set(spec.default.set_name).citation)
    order = {k: i for i, k in enumerate(keys())}
    return sorted(set(found) & set(order), key=order.__getitem__)


def catalogue() -> list[Reference]:
    """Every registered component type, by kind, then name."""
    return sorted((reference(cls) for cls in REGISTRY.types.values()), key=lambda r: (r.kind.split(".")[0], r.name))


def _default(p: dict[str, Any]) -> str:
    value = f"{p['default']:.6g}"
    return f"{value} (from {p['default_from']})" if "default_from" in p else value


def _input_default(p: dict[str, Any]) -> str:
    return "must be connected" if p["default"] is None else f"{p['default']:g} when unconnected"


def text(ref: Reference) -> str:
    """The reference as plain text for a terminal."""
    lines = [f"{ref.name}  ({ref.kind})", "", ref.notes, ""]
    if ref.arguments:
        lines += ["Arguments (besides the name):"] + [f"  {k}: {v}" for k, v in ref.arguments.items()] + [""]
    rows = [(p["name"], p["unit"], _default(p), p["range"], p["description"]) for p in ref.parameters]
    if rows:
        lines.append("Parameters [SI unit]  default  range  meaning:")
        width = max(len(r[0]) for r in rows)
        lines += [f"  {n.ljust(width)}  [{u}]  {d}  {rg}  {m}" for n, u, d, rg, m in rows]
        lines.append("")
    sections = (
        ("Hydraulic ports (connect a port to ports: system.connect('a.P', 'b.A'))", [_port(h) for h in ref.hydraulic]),
        ("Options", [f"  {o['name']} = {o['default']!r}: one of {', '.join(o['choices'])}; {o['description']}" for o in ref.options]),
        ("States", [f"  {s['name']} [{s['unit']}]  {s['description']} (initial: {s['initial']})" for s in ref.states]),
        ("Inputs", [f"  {p['name']} [{p['unit']}]  {p['description']} ({_input_default(p)})" for p in ref.inputs]),
        ("Outputs", [f"  {o['name']} [{o['unit']}]  {o['description']}" for o in ref.outputs]),
        ("Physical limits checked after every run", [_limit(lim) for lim in ref.limits]),
        ("Former names (still accepted)", [f"  {old} -> {new}" for old, new in ref.renamed.items()]),
    )
    for title, body in sections:
        if body:
            lines += [f"{title}:"] + body + [""]
    return "\n".join(lines).rstrip() + "\n"


def _port(h: dict[str, Any]) -> str:
    gives = f"gives the pressure {h['p']}, takes the flow {h['Q']}" if h["kind"] == "pressure" else (
        f"takes the pressure {h['p']}, gives the flow {h['Q']}"
    )
    return f"  {h['name']}: {h['description']}; {h['kind']} port: {gives} (positive {h['Q_positive']})"


def _limit(lim: dict[str, Any]) -> str:
    bounds = f" between {lim['lower']} and {lim['upper']}" if lim["lower"] else ""
    return f"  {lim['signal']}: {lim['kind']}{bounds}"


def markdown(ref: Reference) -> str:
    """The reference as a Markdown section (docs/components.md)."""
    out = [f"### {ref.name}", "", f"`hydroservo.components.{ref.kind}` — {ref.summary}", ""]
    rest = ref.source.split("\n\n", 1)[1] if "\n\n" in ref.source else ""
    if rest:
        out += [_md_block(markdown_prose(rest)), ""]
    if ref.arguments:
        out += ["Arguments besides the name: " + "; ".join(f"`{k}`, {v}" for k, v in ref.arguments.items()), ""]
    if ref.parameters:
        out += ["| parameter | unit | default | range | meaning |", "|---|---|---|---|---|"]
        out += [
            f"| `{p['name']}` | {p['unit']} | {_default(p)} | {p['range']} | {p['description']} |" for p in ref.parameters
        ]
        out.append("")
    if ref.options:
        out += ["| option | default | choices | meaning |", "|---|---|---|---|"]
        out += [f"| `{o['name']}` | `{o['default']}` | {', '.join(o['choices'])} | {o['description']} |" for o in ref.options]
        out.append("")
    if ref.hydraulic:
        out += ["| hydraulic port | kind | pressure | flow (positive) | meaning |", "|---|---|---|---|---|"]
        out += [
            f"| `{h['name']}` | {h['kind']} | `{h['p']}` | `{h['Q']}` ({h['Q_positive']}) | {h['description']} |"
            for h in ref.hydraulic
        ]
        out.append("")
    ports = [("state", s["name"], s["unit"], s["description"]) for s in ref.states]
    ports += [("input", p["name"], p["unit"], f"{p['description']} ({_input_default(p)})") for p in ref.inputs]
    ports += [("output", o["name"], o["unit"], o["description"]) for o in ref.outputs]
    if ports:
        out += ["| signal | name | unit | meaning |", "|---|---|---|---|"]
        out += [f"| {k} | `{n}` | {u} | {d} |" for k, n, u, d in ports]
        out.append("")
    if ref.limits:
        out += ["Physical limits checked after every run: " + "; ".join(_limit(lim).strip() for lim in ref.limits) + ".", ""]
    if ref.renamed:
        out += ["Former names (still accepted): " + ", ".join(f"`{a}` → `{b}`" for a, b in ref.renamed.items()) + ".", ""]
    return "\n".join(out)


def _md_block(doc: str) -> str:
    """Docstring paragraphs for Markdown: indented blocks (equations) as code."""
    out, block = [], []
    for line in doc.splitlines():
        if line.startswith("    "):
            block.append(line[4:])
            continue
        if block:
            out += ["```", *block, "```"]
            block = []
        out.append(line)
    if block:
        out += ["```", *block, "```"]
    return "\n".join(out)
