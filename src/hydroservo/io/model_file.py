"""Model files: a system as human-readable TOML, every dimensional value with its unit.

::

    [model]
    name = "valve-cylinder"
    t_end = "1 s"
    citation = "Efe2014"          # optional: where the model comes from (hydroservo.references)
    status = "example"            # optional: published (a source's model) or example

    [fluid]                       # optional: the oil, named once (hydroservo.fluids)
    name = "iso-vg46"
    temperature = "40 degC"
    bulk_modulus = "1.2 GPa"      # optional: effective, with air and hoses

    [components.supply]
    type = "ConstantPressure"
    p = "210 bar"

    [components.cyl]
    type = "Cylinder"
    A_A = "19.6 cm^2"
    bulk_modulus = "lee"          # options are strings

    [components.valve]
    file = "valve.toml"           # a component parameter file; keys given here override it

    [components.command]
    type = "Table"
    file = "record.csv"           # a Table's time table (CSV: time [s], then values)
    column = "volts"

    [connections]                 # hydraulic port = port(s) it connects to; signal input = output feeding it
    "supply.P" = ["valve.P", "relief.P"]   # one node of three ports
    "valve.A" = "cyl.A"
    "valve.xv" = "spool.xv"

    [initial]                     # optional: number, quantity or expression of parameters
    "cyl.pA" = "50 bar"

    [aliases]                     # optional: named expressions of signals
    y = { expr = "-load.x", unit = "m", description = "retraction" }

:func:`write_model` writes any system in this form and :func:`read_model`
reads it back to the same system: a value given with a unit is written as it
was given ("1500 psi"), any other in SI at full precision, so a round trip
gives the same results. :func:`load_model` reads a built-in model by name or a
model file by path.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from hydroservo.components.base import REGISTRY, Component
from hydroservo.components.signals import Table
from hydroservo.data import model_names, model_text
from hydroservo.errors import HydroservoError, ModelFileError, did_you_mean, shorten
from hydroservo.io.component_file import read_component_file
from hydroservo.io.tables import read_time_table
from hydroservo.io.toml import read_toml, toml_comment, toml_key, toml_quantity, toml_string, toml_value
from hydroservo.system import System
from hydroservo.system.nodes import port_of
from hydroservo.units import UnitChoice, format_quantity, to_si

__all__ = [
    "read_model",
    "write_model",
    "model_to_toml",
    "edited_model_text",
    "checked_model_text",
    "system_from_dict",
    "load_model",
    "builtin_models",
    "available_models",
]

_SECTIONS = ("model", "fluid", "components", "connections", "initial", "aliases")
_FLUID_KEYS = ("name", "temperature", "pressure", "bulk_modulus")
_META = ("citation", "status", "validation")
#: every key [model] may hold
_MODEL_KEYS = ("name", "description", *_META, "t_end", "plots", "plot_units", "units", "metrics", "notes")


def _component_lines(
    comp: Component,
    fluid: bool = False,
    shared: dict[str, str] | None = None,
    taken: dict[str, tuple[float, str | None]] | None = None,
) -> list[str]:
    """``shared``: parameters written as comments, being another component's (name); ``taken``: parameters
    written with another component's value and text (a spool's stroke set on its valve)."""
    lines = [f"[components.{toml_key(comp.name)}]", f"type = {toml_string(type(comp).__name__)}"]
    if comp.unit is not None:
        lines.append(f"unit = {toml_string(comp.unit)}")
    for key, opt in comp.OPTIONS.items():
        lines.append(f"{toml_key(key)} = {toml_string(comp.option(key))}  {toml_comment('one of ' + ', '.join(opt.choices))}")
    for key, spec in comp.PARAMETERS.items():
        value, given = (taken or {}).get(key, (comp.values[key], comp.given.get(key)))
        text = toml_quantity(value, spec.unit, given)
        if spec.fluid and key not in comp.explicit:  # the circuit's fluid, or the default until there is one
            source = "from the circuit fluid" if fluid else "default; a circuit fluid replaces it unless set here"
            lines.append(toml_comment(f"{key} = {text}  # {spec.description}: {source}"))
            continue
        if shared and key in shared:
            lines.append(toml_comment(f"{key} = {text}  # {spec.description}: the stroke of {shared[key]!r}, which drives it"))
            continue
        lines.append(f"{toml_key(key)} = {text}  {toml_comment(spec.description)}")
    for key, val in comp.config().items():
        lines.append(f"{toml_key(key)} = {toml_value(val)}")
    return lines


def model_to_toml(system: System) -> str:
    """The system as a TOML model file (text)."""
    lines = [
        toml_comment(f"hydroservo model file: {system.name}"),
        "# Every dimensional value carries its unit; edit freely and run with `hydroservo simulate FILE`.",
        "",
        "[model]",
        f"name = {toml_string(system.name)}",
    ]
    if system.description:
        lines.append(f"description = {toml_string(system.description)}")
    for key in _META:
        if system.meta.get(key):
            lines.append(f"{key} = {toml_string(system.meta[key])}")
    lines.append(f"t_end = {toml_string(format_quantity(system.t_end, 's'))}")
    if system.plots:
        lines.append(f"plots = {toml_value(system.plots)}  # panels of signals for plots")
    if system.plot_units:
        lines.append(f"plot_units = {toml_value(system.plot_units)}")
    if system.display_units:
        lines.append(f"units = {toml_value(system.display_units)}  # what results are shown in")
    if system.metrics:
        lines.append(f"metrics = {toml_value(system.metrics)}  # what a study measures of each run")
    if system.notes:
        lines.append(f"notes = {toml_value(system.notes)}  # printed with every run")
    if system.fluid is not None:
        given = dict(system.fluid.given)
        lines += ["", "[fluid]", f"name = {toml_string(system.fluid.name)}"]
        temperature = given.get("temperature", format_quantity(system.fluid.temperature, "degC"))
        lines.append(f"temperature = {toml_string(temperature)}")
        if system.fluid.pressure:
            lines.append(f"pressure = {toml_quantity(system.fluid.pressure, 'Pa', given.get('pressure'))}")
        if system.fluid.bulk_modulus is not None:
            text = toml_quantity(system.fluid.bulk_modulus, "Pa", given.get("bulk_modulus"))
            lines.append(f"bulk_modulus = {text}  # effective")
    strokes: dict[str, dict[str, str]] = {}  # a valve's stroke is written once, on the spool that drives it
    taken: dict[str, dict[str, tuple[float, str | None]]] = {}  # ... with the valve's value if set only there
    for valve, spool in system.stroke_pairs():
        (vc, vp), (sc, sp) = valve.split("."), spool.split(".")
        strokes.setdefault(vc, {})[vp] = sc
        if vp in system[vc].explicit and sp not in system[sc].explicit:
            taken.setdefault(sc, {})[sp] = (system[vc].values[vp], system[vc].given.get(vp))
    for comp in system.components.values():
        lines += ["", *_component_lines(comp, system.fluid is not None, strokes.get(comp.name), taken.get(comp.name))]
    lines += ["", "[connections]  # hydraulic port = the ports it connects to; signal input = the output that feeds it"]
    for node in system.nodes():
        first, *others = node.ports
        lines.append(f"{toml_string(first)} = {toml_value(others[0] if len(others) == 1 else others)}")
    for target, source in system.connections.items():
        lines.append(f"{toml_string(target)} = {toml_string(source)}")
    if system.initial:
        lines += ["", "[initial]"]
        for state, val in system.initial.items():
            lines.append(f"{toml_string(state)} = {toml_value(system.initial_given.get(state, val))}")
    if system.aliases:
        lines += ["", "[aliases]"]
        for name, alias in system.aliases.items():
            entry = {"expr": alias.expr, "unit": alias.unit, "description": alias.description}
            lines.append(f"{toml_key(name)} = {toml_value(entry)}")
    return "\n".join(lines) + "\n"


def edited_model_text(text: str, system: System, keys: Sequence[str], where: str = "model file") -> str | None:
    """``text``, the model file ``system`` was read from, with the values of ``keys`` (``"comp.param"``: what was
    set since) written as ``system`` holds them (in the unit they were given in), and any former type or
    parameter name written as it is now called; every comment, the order and the layout of the rest are kept.

    None if the file's text does not describe ``system`` after the edit (read back and compared: a value the
    file cannot hold where it is, such as a stroke written on another component), so that the caller writes the
    whole model instead (:func:`model_to_toml`).
    """
    import tomllib
    import warnings

    from hydroservo.io.toml import edit_toml

    try:
        components = tomllib.loads(text).get("components", {})
    except tomllib.TOMLDecodeError:
        return None
    changes: dict[tuple[str, ...], str | None] = {}
    renames: dict[tuple[str, ...], str] = {}
    for cname, entry in components.items():
        comp = system.components.get(cname)
        if comp is None or not isinstance(entry, dict):
            return None
        if REGISTRY.renamed.get(str(entry.get("type")), "") == type(comp).__name__:
            changes[("components", cname, "type")] = toml_string(type(comp).__name__)
        for old, new in comp.RENAMED.items():
            if old in entry and new not in entry:
                renames[("components", cname, old)] = new
    for key in keys:
        cname, pname = key.split(".", 1)
        comp = system.components[cname]
        pname = comp.RENAMED.get(pname, pname) if pname not in comp.PARAMETERS and pname not in comp.OPTIONS else pname
        if pname in comp.OPTIONS:
            value = toml_string(comp.option(pname))
        else:
            value = toml_quantity(comp.values[pname], comp.PARAMETERS[pname].unit, comp.given.get(pname))
        written = [old for (_, c, old), new in renames.items() if c == cname and new == pname]
        changes[("components", cname, written[0] if written else pname)] = value  # renamed after the change
    edited = edit_toml(text, changes, renames)
    try:
        with warnings.catch_warnings():  # the read-back is a check: what it would warn of was said at loading
            warnings.simplefilter("ignore")
            again = system_from_dict(tomllib.loads(edited), where=where, base=_base(system))
    except HydroservoError:
        return None
    same = again.parameter_values() == system.parameter_values() and all(
        again.components[c].option_values == comp.option_values for c, comp in system.components.items()
        if c in again.components
    ) and list(again.components) == list(system.components)
    return edited if same else None


def checked_model_text(text: str, system: System, what: str = "model file") -> str:
    """``text``, a model file written of ``system``, if it loads and describes ``system``: the same components
    and parameter values, options, connections, initial values and aliases, and every expression in it readable.
    Whatever a name or a description held, what is written loads; a text that would not is refused here, before
    anything is written.

    Raises
    ------
    ModelFileError
        Naming ``what`` and what would not load or would differ.
    """
    import tomllib
    import warnings

    from hydroservo.system.expressions import names_in

    try:
        data = tomllib.loads(text)
        with warnings.catch_warnings():  # the read-back is a check: what it would warn of is said elsewhere
            warnings.simplefilter("ignore")
            again = system_from_dict(data, where=what, base=_base(system))
        for name, alias in again.aliases.items():
            names_in(alias.expr, f"alias {name!r}")
        for state, value in again.initial.items():
            if isinstance(value, str):
                names_in(value, f"initial {state!r}")
    except (tomllib.TOMLDecodeError, HydroservoError) as exc:
        raise ModelFileError(f"{what} of {shorten(system.name)!r} would not load ({exc}); nothing was written") from None

    def described(s: System) -> tuple[Any, ...]:
        return (
            s.name, s.t_end, list(s.components), s.parameter_values(as_run=True),  # a stroke is written once
            {c: comp.option_values for c, comp in s.components.items()},
            {frozenset(node.ports) for node in s.nodes()}, dict(s.connections), dict(s.initial),
            dict(s.aliases),
        )

    if described(again) != described(system):
        raise ModelFileError(
            f"{what} of {shorten(system.name)!r}: does not read back as the same model; nothing was written"
        )
    return text


def _base(system: System) -> Path | None:
    """The folder a model file's relative paths (tables) are read from: the file's."""
    source = str(system.source or "")
    return None if not source or source.startswith("built-in:") else Path(source).parent


def write_model(system: System, path: str | Path) -> Path:
    """Write ``system`` as a TOML model file (UTF-8), read back first: what is written loads as ``system``
    (:func:`checked_model_text`)."""
    path = Path(path)
    text = checked_model_text(model_to_toml(system), system, f"model file {str(path)!r}")
    path.write_text(text, encoding="utf-8")
    return path


def read_model(path: str | Path) -> System:
    """Read a TOML model file into a :class:`System`.

    Raises
    ------
    ModelFileError
        For a missing or malformed file, an unknown component type or parameter,
        a value of the wrong dimension or out of range, or a bad connection; the
        message names the file, the table and the key.
    """
    path = Path(path)
    data = read_toml(path, "model file", ModelFileError)
    system = system_from_dict(data, where=str(path), base=path.parent)
    system.source = str(path)
    return system


def builtin_models() -> dict[str, dict[str, str]]:
    """The built-in models: name -> description, citation, status and validation status."""
    import tomllib

    out = {}
    for name in model_names():
        meta = tomllib.loads(model_text(name)).get("model", {})
        out[name] = {k: str(meta.get(k, "")) for k in ("description", *_META)}
    return out


def available_models() -> dict[str, str]:
    """Names and descriptions of the built-in systems."""
    return {name: meta["description"] for name, meta in builtin_models().items()}


def load_model(name_or_path: str | Path) -> System:
    """A built-in system by name (:func:`builtin_models`), or a system from a TOML model file."""
    import tomllib

    key = str(name_or_path)
    if not key.strip():
        raise ModelFileError(
            f"model name {key!r}: empty; expected a built-in model ({', '.join(model_names())}) or a model file (.toml)"
        )
    if key in model_names():
        system = system_from_dict(tomllib.loads(model_text(key)), where=f"built-in model {key!r}")
        system.source = f"built-in:{key}"
        return system
    path = Path(key)
    if path.suffix.lower() == ".toml" or path.exists():
        return read_model(path)
    raise ModelFileError(
        f"{key!r} is neither a built-in model{did_you_mean(key, model_names())} ({', '.join(model_names())}) nor a "
        "model file (.toml)"
    )


def _component_spec(spec: Any, ctx: str, base: Path | None) -> dict[str, Any]:
    """A component table with its included parameter file (``file = "x.toml"``) merged in, or its time table read."""
    if not isinstance(spec, dict):
        raise ModelFileError(f"{ctx}: expected a table with a 'type' (one of {', '.join(sorted(REGISTRY.types))})")
    if "file" not in spec:
        return spec
    file = Path(str(spec["file"]))
    if not file.is_absolute() and base is not None:
        file = base / file
    try:
        if file.suffix.lower() == ".toml":  # a component parameter file
            return {**read_component_file(file), **{k: v for k, v in spec.items() if k != "file"}}
        # a time table of a Table component
        column = spec.get("column", 1)
        times, values = read_time_table(file, column, what=ctx)
    except HydroservoError as exc:  # the table's reader names the component already (what=ctx)
        text = str(exc)
        raise ModelFileError(text if text.startswith(ctx) else f"{ctx}: {text}") from None
    rest = {k: v for k, v in spec.items() if k not in ("file", "column")}
    source = {"file": str(spec["file"]), "column": column}
    return {**rest, "times": times, "values": values, "source": source}


def _add_components(system: System, comps: Any, where: str, base: Path | None) -> None:
    if not isinstance(comps, dict) or not comps:
        raise ModelFileError(f"{where}: no [components.NAME] tables; a model needs at least one component")
    for cname, raw in comps.items():
        ctx = f"{where}: [components.{cname}]"
        spec = _component_spec(raw, ctx, base)
        if "type" not in spec:
            raise ModelFileError(f"{ctx}: missing 'type' (one of {', '.join(sorted(REGISTRY.types))})")
        kind = spec["type"]
        cls = REGISTRY.resolve(kind)
        if cls is None:
            raise ModelFileError(
                f"{ctx}: unknown component type {kind!r}{did_you_mean(kind, REGISTRY.types)}; known: "
                f"{', '.join(sorted(REGISTRY.types))}"
            )
        kwargs = {k: v for k, v in spec.items() if k != "type"}
        if "source" in kwargs and cls is not Table:
            raise ModelFileError(f"{ctx}: file {kwargs['source']['file']!r}: expected a component file (.toml)")
        try:
            system.add(cls(cname, **kwargs))
        except (HydroservoError, TypeError) as exc:
            if isinstance(raw, dict) and "file" in raw and str(raw["file"]).lower().endswith(".toml"):
                ctx += f" with its parameter file {str(raw['file'])!r}"  # the value may be in either
            raise ModelFileError(f"{ctx}: {exc}") from None


def _set_fluid(system: System, spec: Any, where: str) -> None:
    if spec is None:
        return
    if not isinstance(spec, dict) or "name" not in spec:
        raise ModelFileError(f'{where}: [fluid]: expected a table with a name, e.g. name = "iso-vg46", temperature = "40 degC"')
    unknown = set(spec) - set(_FLUID_KEYS)
    if unknown:
        raise ModelFileError(f"{where}: [fluid] {', '.join(sorted(unknown))}: unknown; expected {', '.join(_FLUID_KEYS)}")
    try:
        system.set_fluid(**{k: v for k, v in spec.items()})
    except HydroservoError as exc:
        raise ModelFileError(f"{where}: [fluid] {exc}") from None


def _connect(system: System, key: str, value: Any, where: str) -> None:
    """One line of [connections]: hydraulic ports (``port = port`` or ``port = [ports]``) or a signal (``input = output``)."""
    hydraulic = port_of(system.components, key) is not None
    many = isinstance(value, list) and value and all(isinstance(v, str) for v in value)
    if not (isinstance(value, str) or (hydraulic and many)):
        expected = "the name of a hydraulic port or a list of them" if hydraulic else "the name of an output"
        raise ModelFileError(f"{where}: [connections] {key!r} = {value!r}: expected {expected}")
    try:
        if hydraulic or port_of(system.components, value) is not None:
            system.connect(key, *([value] if isinstance(value, str) else value))
        else:
            system.connect(value, key)
    except HydroservoError as exc:
        raise ModelFileError(f"{where}: [connections] {exc}") from None


def system_from_dict(data: dict[str, Any], where: str = "model", base: Path | None = None) -> System:
    """Build a system from the parsed contents of a model file.

    A component table may name a component parameter file, ``file = "valve.toml"``
    (relative to ``base``, the model file's folder), whose ``[component]`` table
    supplies the type and parameters; keys in the model file override it. A
    ``Table`` component may name a CSV time table the same way.
    """
    unknown = set(data) - set(_SECTIONS)
    if unknown:
        raise ModelFileError(
            f"{where}: unknown section(s) {', '.join(sorted(unknown))}; expected {', '.join(_SECTIONS)}"
        )
    meta = data.get("model", {})
    if not isinstance(meta, dict):
        raise ModelFileError(f"{where}: [model] = {shorten(repr(meta))}: expected a table (name, t_end, ...)")
    for key in meta:  # a misspelt key (tend = "0.5 s") would be dropped and the run made with the default
        if key not in _MODEL_KEYS:
            raise ModelFileError(
                f"{where}: [model] {shorten(str(key))!r}: unknown key{did_you_mean(str(key), _MODEL_KEYS)}; expected one "
                f"of {', '.join(_MODEL_KEYS)}"
            )
    try:
        t_end = to_si(meta.get("t_end", 1.0), "s", what="[model] t_end")
    except HydroservoError as exc:
        raise ModelFileError(f"{where}: {exc}") from None
    system = System(str(meta.get("name", Path(where).stem)), str(meta.get("description", "")), t_end=t_end)
    system.meta = {k: str(meta[k]) for k in _META if k in meta}
    plots = meta.get("plots", [])
    panels_ok = isinstance(plots, list) and all(
        isinstance(p, str) or (isinstance(p, list) and p and all(isinstance(n, str) for n in p)) for p in plots
    )
    if not panels_ok:
        raise ModelFileError(
            f"{where}: [model] plots = {plots!r}: expected a list of panels, each a signal name or a non-empty "
            'list of names, e.g. [["p1", "p2"], ["y"]]'
        )
    system.plots = [[p] if isinstance(p, str) else list(p) for p in plots]
    units = meta.get("plot_units", {})
    if not isinstance(units, dict) or not all(isinstance(v, str) for v in units.values()):
        raise ModelFileError(
            f'{where}: [model] plot_units = {units!r}: expected a table of signal = "unit", e.g. {{ p1 = "psi" }}'
        )
    system.plot_units = {str(k): v for k, v in units.items()}
    shown = meta.get("units", [])
    if isinstance(shown, str):
        shown = [shown]
    if not (isinstance(shown, list) and all(isinstance(u, str) for u in shown)):
        raise ModelFileError(
            f'{where}: [model] units = {shown!r}: expected a list of units to show results in, e.g. ["psi", "in", '
            '"Q=in^3/s"]'
        )
    try:
        UnitChoice.parse(shown, what="[model] units")
    except HydroservoError as exc:
        raise ModelFileError(f"{where}: {exc}") from None
    system.display_units = list(shown)
    metrics = meta.get("metrics", [])
    if not (isinstance(metrics, list) and all(isinstance(m, str) for m in metrics)):
        raise ModelFileError(
            f'{where}: [model] metrics = {metrics!r}: expected a list of metrics, e.g. ["final(x_mm)", "peak(cyl.pA)"]'
        )
    system.metrics = list(metrics)
    notes = meta.get("notes", [])
    if not (isinstance(notes, list) and all(isinstance(n, str) for n in notes)):
        raise ModelFileError(
            f'{where}: [model] notes = {notes!r}: expected a list of texts, e.g. ["the 86 MPa peak is in the '
            "source's result too (docs/hopsan.md)\"]"
        )
    system.notes = [" ".join(n.split()) for n in notes]
    _set_fluid(system, data.get("fluid"), where)
    _add_components(system, data.get("components"), where, base)
    for target, source in data.get("connections", {}).items():
        _connect(system, target, source, where)
    try:
        for state, val in data.get("initial", {}).items():
            system.set_initial(state, val)
        for name, alias in data.get("aliases", {}).items():
            if isinstance(alias, str):
                system.alias(name, alias)
            elif isinstance(alias, dict) and "expr" in alias:
                system.alias(name, alias["expr"], alias.get("unit", ""), alias.get("description", ""))
            else:
                raise ModelFileError(f"[aliases] {name}: expected an expression or {{ expr = ..., unit = ... }}")
    except HydroservoError as exc:
        raise ModelFileError(f"{where}: {exc}") from None
    return system
