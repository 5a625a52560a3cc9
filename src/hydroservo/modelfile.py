"""Model files: a system as human-readable TOML, every dimensional value with its unit.

::

    [model]
    name = "valve-cylinder"
    t_end = "1 s"

    [components.supply]
    type = "ConstantPressure"
    p = "210 bar"

    [components.cyl]
    type = "Cylinder"
    A_A = "19.6 cm^2"
    bulk_modulus = "lee"          # options are strings

    [connections]                 # input = output feeding it
    "valve.pS" = "supply.p"

    [initial]                     # optional: number, quantity or expression of parameters
    "cyl.pA" = "50 bar"

    [aliases]                     # optional: named expressions of signals
    y = { expr = "-load.x", unit = "m", description = "retraction" }

:func:`write_model` writes any system in this form and :func:`read_model`
reads it back to the same system (parameters are written in SI with full
precision, so a round trip gives the same results).
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from hydroservo.components import REGISTRY
from hydroservo.errors import HydroservoError, ModelFileError
from hydroservo.system import System
from hydroservo.units import format_quantity, to_si

__all__ = ["read_model", "write_model", "model_to_toml", "system_from_dict"]


def _q(s: str) -> str:
    """A TOML basic string."""
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _value(v: Any) -> str:
    if isinstance(v, str):
        return _q(v)
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(float(v))
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def _key(k: str) -> str:
    return k if k.replace("_", "a").replace("-", "a").isalnum() else _q(k)


def model_to_toml(system: System) -> str:
    """The system as a TOML model file (text)."""
    lines = [
        f"# hydroservo model file: {system.name}",
        "# Every dimensional value carries its unit; edit freely and run with `hydroservo simulate FILE`.",
        "",
        "[model]",
        f"name = {_q(system.name)}",
    ]
    if system.description:
        lines.append(f"description = {_q(system.description)}")
    lines.append(f"t_end = {_q(format_quantity(system.t_end, 's'))}")
    if system.plots:
        lines.append(f"plots = {_value(system.plots)}  # panels of signals for plots")
    if system.plot_units:
        lines.append(f"plot_units = {_value(system.plot_units)}")
    for cname, comp in system.components.items():
        lines += ["", f"[components.{cname}]", f"type = {_q(type(comp).__name__)}"]
        if comp.unit is not None:
            lines.append(f"unit = {_q(comp.unit)}")
        for key, opt in comp.OPTIONS.items():
            lines.append(f"{key} = {_q(comp.option(key))}  # one of {', '.join(opt.choices)}")
        for key, spec in comp.PARAMETERS.items():
            val = comp.values[key]
            text = _value(val) if spec.unit == "" else _q(format_quantity(val, spec.unit))
            lines.append(f"{key} = {text}  # {spec.description}")
        for key, val in comp.config().items():
            lines.append(f"{key} = {_value(val)}")
    lines += ["", "[connections]  # input = the output that feeds it"]
    for target, source in system.connections.items():
        lines.append(f"{_q(target)} = {_q(source)}")
    if system.initial:
        lines += ["", "[initial]"]
        for state, val in system.initial.items():
            lines.append(f"{_q(state)} = {_value(val)}")
    if system.aliases:
        lines += ["", "[aliases]"]
        for name, alias in system.aliases.items():
            lines.append(
                f"{name} = {_value({'expr': alias.expr, 'unit': alias.unit, 'description': alias.description})}"
            )
    return "\n".join(lines) + "\n"


def read_toml(path: str | Path, what: str, error: type[HydroservoError] = ModelFileError) -> dict[str, Any]:
    """Parse a TOML file; an unreadable or malformed file raises ``error`` naming ``what`` and the path."""
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as exc:
        raise error(f"{what} {str(path)!r}: cannot read ({exc.strerror})") from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{what} {str(path)!r}: malformed TOML: {exc}") from None


def write_model(system: System, path: str | Path) -> Path:
    """Write ``system`` as a TOML model file."""
    path = Path(path)
    path.write_text(model_to_toml(system))
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


def system_from_dict(data: dict[str, Any], where: str = "model", base: Path | None = None) -> System:
    """Build a system from the parsed contents of a model file.

    A component table may name a component parameter file, ``file = "valve.toml"``
    (relative to ``base``, the model file's folder), whose ``[component]`` table
    supplies the type and parameters; keys in the model file override it.
    """
    unknown = set(data) - {"model", "components", "connections", "initial", "aliases"}
    if unknown:
        raise ModelFileError(
            f"{where}: unknown section(s) {', '.join(sorted(unknown))}; expected model, components, connections, initial, aliases"
        )
    meta = data.get("model", {})
    try:
        t_end = to_si(meta.get("t_end", 1.0), "s", what="[model] t_end")
    except HydroservoError as exc:
        raise ModelFileError(f"{where}: {exc}") from None
    system = System(str(meta.get("name", Path(where).stem)), str(meta.get("description", "")), t_end=t_end)
    plots = meta.get("plots", [])
    if not isinstance(plots, list) or not all(isinstance(p, (str, list)) for p in plots):
        raise ModelFileError(f"{where}: [model] plots: expected a list of signal names or lists of names")
    system.plots = [[p] if isinstance(p, str) else [str(n) for n in p] for p in plots]
    system.plot_units = {str(k): str(v) for k, v in meta.get("plot_units", {}).items()}
    comps = data.get("components")
    if not isinstance(comps, dict) or not comps:
        raise ModelFileError(f"{where}: no [components.NAME] tables; a model needs at least one component")
    for cname, spec in comps.items():
        ctx = f"{where}: [components.{cname}]"
        if isinstance(spec, dict) and "file" in spec:
            from hydroservo.identification.files import read_component_file

            included = Path(str(spec["file"]))
            if not included.is_absolute() and base is not None:
                included = base / included
            try:
                spec = {**read_component_file(included), **{k: v for k, v in spec.items() if k != "file"}}
            except HydroservoError as exc:
                raise ModelFileError(f"{ctx}: {exc}") from None
        if not isinstance(spec, dict) or "type" not in spec:
            raise ModelFileError(f"{ctx}: missing 'type' (one of {', '.join(sorted(REGISTRY.types))})")
        kind = spec["type"]
        if kind not in REGISTRY.types:
            raise ModelFileError(f"{ctx}: unknown component type {kind!r}; known: {', '.join(sorted(REGISTRY.types))}")
        kwargs = {k: v for k, v in spec.items() if k != "type"}
        try:
            system.add(REGISTRY.types[kind](cname, **kwargs))
        except HydroservoError as exc:
            raise ModelFileError(f"{ctx}: {exc}") from None
        except TypeError as exc:
            raise ModelFileError(f"{ctx}: {exc}") from None
    for target, source in data.get("connections", {}).items():
        sources = [source] if isinstance(source, str) else None
        if sources is None:
            raise ModelFileError(f"{where}: [connections] {target!r}: expected the name of an output, got {source!r}")
        try:
            system.connect(sources[0], target)
        except HydroservoError as exc:
            raise ModelFileError(f"{where}: [connections] {exc}") from None
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
