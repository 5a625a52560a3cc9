"""A model as an FMU: FMI 2.0 Model Exchange and Co-Simulation in one file (docs/fmu.md).

:func:`export_fmu` writes ``NAME.fmu``, a zip archive that any FMI 2.0 host
(Simulink, Dymola, OpenModelica, Amesim, Simcenter, FMPy, a real-time rig)
imports:

* ``modelDescription.xml``: every parameter (``causality="parameter"``,
  tunable where the rates or outputs depend on it, fixed where it only sets
  the initial states; its range as ``min``/``max``), the inputs, the states
  (outputs too, with their nominal magnitudes), their derivatives and the
  outputs, each with its unit, defined against the SI base units; the exact
  dependencies of each derivative and output on the states and inputs (from
  the model's sparsity); a default experiment.
* ``binaries/<platform>/NAME.so`` (``.dylib``, ``.dll``): built here with the
  system's C compiler from the sources below; only the ``fmi2`` functions are
  exported.
* ``sources/``: the same C code, for a host that builds FMUs itself: the
  model's functions (CasADi), the fixed-step stepper of
  :mod:`hydroservo.codegen.c`, the forward derivatives of the rates and
  outputs (``NAME_fmu_model.c``, for ``fmi2GetDirectionalDerivative``) and
  ``NAME_fmi2.c``, the FMI interface, which calls the stepper's C API.

FMU states can be taken, restored and serialised; directional derivatives are
exact.

**Model Exchange** gives the host the model in continuous time (the host's
integrator steps it, as CVODES does inside hydroservo). **Co-Simulation**
steps it with the stepper's fixed-step method (``rk4`` by default; ``bdf2``
for stiff circuits, but not across a right-hand side that jumps, docs/fmu.md)
at the step chosen at export, a communication step being a whole number of
those steps; or, with ``method="rodas3"``, ``"ros23"`` or ``"dopri5"``, with a variable-step
method with error control (docs/engine.md, "Compiled solvers") to the
accuracy chosen at export, over any communication step. Co-simulation starts at t = 0. The model has no events, no integer or boolean variables.

An input (``valve.u``) is added to whatever drives it inside the system, as
in :func:`~hydroservo.codegen.c.export_c`.
"""

from __future__ import annotations

import hashlib
import html
import math
import os
import re
import sys
import tempfile
import uuid
import xml.etree.ElementTree as ET
import zipfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from hydroservo.codegen.c import (
    ADAPTIVE_METHODS,
    METHODS,
    NEWTON_TOLERANCE,
    c_identifier,
    check_inputs,
    check_name,
    check_step,
    compile_library,
    compiler,
    export_c,
    fill_template,
    library_suffix,
)
from hydroservo.data import c_template
from hydroservo.errors import ParameterError, shorten
from hydroservo.io.files import OutputFolder
from hydroservo.io.text import xml_text
from hydroservo.system.assembly import assemble
from hydroservo.system.integration import DEFAULT_ACCURACY, tolerances
from hydroservo.system.model import Model
from hydroservo.system.native import _c_comment
from hydroservo.system.system import System
from hydroservo.units import si_definition
from hydroservo.version import __version__

__all__ = ["FmuExport", "Variable", "check_cosimulation_method", "export_fmu", "fmu_platform", "model_description", "variables"]

#: The Co-Simulation step when none is given [s].
DEFAULT_STEP = 1e-4

#: The Co-Simulation method when none is given.
DEFAULT_METHOD = "rk4"

#: A name FMI's structured naming convention reads as written: identifiers joined by dots, or der(...) of one.
_STRUCTURED = re.compile(r"(der\()?[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)*\)?")


@dataclass(frozen=True)
class Variable:
    """A variable of the FMU: its name there, the hydroservo name it stands for, its kind, unit and description."""

    name: str
    signal: str
    kind: str  # "parameter", "input", "state", "derivative" or "output"
    unit: str
    description: str


@dataclass(frozen=True)
class FmuExport:
    """What :func:`export_fmu` wrote: the file, its model identifier and GUID, and its variables.

    ``variables`` are in value-reference order (the parameters from 0, then the inputs, the states, the
    states' derivatives, the outputs), named as in the FMU; ``tunable`` says which parameters may change
    after the initialisation; ``platform`` is the folder of the binary built (None: sources only).
    """

    path: Path
    name: str
    model: str
    guid: str
    step: float
    method: str
    variables: tuple[Variable, ...]
    defaults: tuple[float, ...]
    tunable: tuple[bool, ...]
    platform: str | None
    files: tuple[str, ...]

    def _named(self, kind: str) -> tuple[str, ...]:
        return tuple(v.name for v in self.variables if v.kind == kind)

    @property
    def parameters(self) -> tuple[str, ...]:
        return self._named("parameter")

    @property
    def inputs(self) -> tuple[str, ...]:
        return self._named("input")

    @property
    def states(self) -> tuple[str, ...]:
        return self._named("state")

    @property
    def outputs(self) -> tuple[str, ...]:
        return self._named("output")

    @property
    def units(self) -> dict[str, str]:
        """The unit of each variable, by its name in the FMU."""
        return {v.name: v.unit for v in self.variables}

    def value_reference(self, name: str) -> int:
        """The value reference of a variable (``der(x)`` for a state's derivative), by its name in the FMU."""
        for vr, v in enumerate(self.variables):
            if v.name == name:
                return vr
        raise ParameterError(f"FMU {self.path.name}: no variable {shorten(name)!r}")


def fmu_platform() -> str:
    """The FMI 2.0 platform folder of this machine's binaries: ``linux64``, ``darwin64``, ``win64`` (or 32)."""
    bits = "64" if sys.maxsize > 2**32 else "32"
    system = "darwin" if sys.platform == "darwin" else "win" if sys.platform == "win32" else "linux"
    return system + bits


@dataclass(frozen=True)
class _Structure:
    """What the model description needs from the model: tunable parameters, dependencies."""

    tunable: tuple[bool, ...]
    derivative_dependencies: list[list[int]]  # per state: states (0..nx-1) and inputs (nx..nx+ni-1)
    output_dependencies: list[list[int]]  # per output, as above


def _structure(model: Model, n_parameters: int) -> _Structure:
    """Which parameters the rates or outputs depend on, and on which states and inputs each rate and output
    depends (CasADi's structural sparsity: a dependency that is multiplied by zero still counts)."""
    t, x, p = ca.SX.sym("t"), ca.SX.sym("x", model.nx), ca.SX.sym("p", model.np)
    rates, outputs = model.f(t, x, p), model.outputs(t, x, p)
    both = ca.vertcat(rates, outputs)
    used = ca.jacobian(both, p[:n_parameters]).sparsity() if n_parameters else None
    tunable = tuple(bool(used.colind()[i + 1] > used.colind()[i]) for i in range(n_parameters)) if used else ()
    knowns = ca.vertcat(x, p[n_parameters:])

    def rows(expr: Any) -> list[list[int]]:
        if expr.numel() == 0:
            return []
        pattern = ca.jacobian(expr, knowns).sparsity()
        dense = np.array(ca.DM(pattern, 1).full(), dtype=bool)
        return [list(np.flatnonzero(row)) for row in dense]

    return _Structure(tunable, rows(rates), rows(outputs))


def _number(value: float) -> str:
    """A float for an XML attribute: the shortest text that reads back as the same double."""
    return repr(float(value))


def _unit_definitions(units: Sequence[str]) -> ET.Element:
    """``<UnitDefinitions>``: each unit against the SI base units (a unit with a fractional exponent, such
    as an orifice coefficient's Pa^0.5, is declared by name only: FMI's exponents are integers)."""
    element = ET.Element("UnitDefinitions")
    for unit in sorted(set(units) - {""}):
        factor, offset, exponents = si_definition(unit)
        item = ET.SubElement(element, "Unit", name=unit)
        if all(float(x).is_integer() for x in exponents.values()):
            base = {k: str(int(x)) for k, x in exponents.items() if x}
            if factor != 1.0:
                base["factor"] = _number(factor)
            if offset != 0.0:
                base["offset"] = _number(offset)
            ET.SubElement(item, "BaseUnit", base)
    return element


#: The suffix a variable takes when an earlier kind has its name (a supply's parameter p and its output p).
_SUFFIX = {"input": "_in", "state": "_state", "output": "_out"}


def variables(system: System, model: Model, inputs: Sequence[str]) -> list[Variable]:
    """The FMU's variables in value-reference order: the parameters, the inputs, the states, their derivatives,
    the outputs (``model``: the assembly of ``system`` with ``inputs`` as extra parameters).

    FMI needs unique names: a name an earlier kind has (a supply's parameter ``supply.p`` and its output
    ``supply.p``) takes a suffix (``supply.p_out``), and its description says what it stands for.
    """
    n_par = len(model.parameter_names) - len(inputs)
    params, ports = system.declared("PARAMETERS"), system.declared("INPUTS")
    signals = {n: d.description for n, d in {**system.declared("STATES"), **system.declared("OUTPUTS")}.items()}
    signals.update({k: a.description or f"= {a.expr}" for k, a in system.aliases.items()})
    found: list[Variable] = []
    taken: set[str] = set()

    def add(signal: str, kind: str, unit: str, description: str) -> None:
        name = signal
        while name in taken:
            name += _SUFFIX[kind]
        if name != signal:
            description = f"{description} (the {kind} {signal}: a variable before it has that name)"
        taken.add(name)
        found.append(Variable(name, signal, kind, unit, description))

    for pname in model.parameter_names[:n_par]:
        add(pname, "parameter", model.parameter_units[pname], params[pname].description)
    for target, pname in zip(inputs, model.parameter_names[n_par:]):
        add(target, "input", model.parameter_units[pname], f"{ports[target].description}; added to what drives it in the system")
    for sname in model.state_names:
        add(sname, "state", model.units[sname], signals.get(sname, "a state"))
    states = [v for v in found if v.kind == "state"]
    for v in states:
        found.append(Variable(f"der({v.name})", f"der({v.signal})", "derivative", _rate_unit(v.unit), f"rate of {v.name}"))
    for oname in model.output_names:
        add(oname, "output", model.units[oname], signals.get(oname, ""))
    return found


def model_description(
    system: System,
    model: Model,
    *,
    name: str,
    guid: str,
    step: float,
    inputs: Sequence[str],
    sources: Sequence[str],
) -> tuple[str, list[Variable], _Structure]:
    """``modelDescription.xml`` of ``system`` (``model``: its assembly with ``inputs`` as extra parameters),
    its variables in value-reference order, and the model's structure."""
    defaults = system.parameter_vector()
    n_par = len(defaults)
    spec = system.declared("PARAMETERS")
    structure = _structure(model, n_par)
    every = variables(system, model, inputs)
    structured = all(_STRUCTURED.fullmatch(v.name) for v in every)
    rtol, _ = tolerances(DEFAULT_ACCURACY)
    root = ET.Element(
        "fmiModelDescription",
        {
            "fmiVersion": "2.0",
            "modelName": xml_text(system.name),
            "guid": guid,
            "description": xml_text(system.description or f"hydroservo model {system.name!r}"),
            "generationTool": f"hydroservo {__version__}",
            "variableNamingConvention": "structured" if structured else "flat",
            "numberOfEventIndicators": "0",
        },
    )
    common = {"modelIdentifier": name, "canNotUseMemoryManagementFunctions": "false", "canGetAndSetFMUstate": "true",
              "canSerializeFMUstate": "true", "providesDirectionalDerivative": "true"}  # fmt: skip
    me = ET.SubElement(
        root, "ModelExchange", {**common, "completedIntegratorStepNotNeeded": "false", "needsExecutionTool": "false"}
    )
    cs = ET.SubElement(
        root,
        "CoSimulation",
        {**common, "canHandleVariableCommunicationStepSize": "true", "canInterpolateInputs": "false",
         "maxOutputDerivativeOrder": "0", "canRunAsynchronuously": "false", "needsExecutionTool": "false"},
    )  # fmt: skip
    for kind in (me, cs):
        files = ET.SubElement(kind, "SourceFiles")
        for source in sources:
            ET.SubElement(files, "File", name=source)
    root.append(_unit_definitions([v.unit for v in every]))
    categories = ET.SubElement(root, "LogCategories")
    ET.SubElement(categories, "Category", name="logStatusError", description="errors: why a call was refused")
    ET.SubElement(
        root,
        "DefaultExperiment",
        startTime="0.0",
        stopTime=_number(system.t_end),
        tolerance=_number(rtol),
        stepSize=_number(step),
    )
    model_variables = ET.SubElement(root, "ModelVariables")
    index = {v.name: i + 1 for i, v in enumerate(every)}  # ScalarVariable indices count from 1
    state_index = [index[v.name] for v in every if v.kind == "state"]
    known_index = state_index + [index[v.name] for v in every if v.kind == "input"]
    n_state = 0
    for vr, v in enumerate(every):
        attributes = {"name": v.name, "valueReference": str(vr)}
        if v.description:
            attributes["description"] = xml_text(v.description)
        real = {"unit": v.unit} if v.unit else {}
        if v.kind == "parameter":
            param = spec[v.signal]
            tunable = structure.tunable[vr]
            attributes.update(causality="parameter", variability="tunable" if tunable else "fixed", initial="exact")
            real["start"] = _number(defaults[vr])
            for bound, inclusive, inward in (("min", param.min_inclusive, math.inf), ("max", param.max_inclusive, -math.inf)):
                value = getattr(param, bound)
                if value is not None and math.isfinite(value):  # FMI's bounds are inclusive: an excluded one moves in
                    real[bound] = _number(value if inclusive else math.nextafter(value, inward))
        elif v.kind == "input":
            attributes.update(causality="input", variability="continuous")
            real["start"] = "0.0"
        elif v.kind == "state":
            attributes.update(causality="output", variability="continuous", initial="calculated")
            real["nominal"] = _number(model.nominal[n_state])
            n_state += 1
        elif v.kind == "derivative":
            attributes.update(causality="local", variability="continuous")
            real["derivative"] = str(index[v.name[4:-1]])
        else:
            attributes.update(causality="output", variability="continuous")
        ET.SubElement(ET.SubElement(model_variables, "ScalarVariable", attributes), "Real", real)

    def dependencies(known: Sequence[int]) -> str:
        return " ".join(str(known_index[k]) for k in known)

    derivatives = [index[v.name] for v in every if v.kind == "derivative"]
    outputs = [index[v.name] for v in every if v.kind == "output"]
    element = ET.SubElement(root, "ModelStructure")
    outs = ET.SubElement(element, "Outputs")
    for i in state_index:
        ET.SubElement(outs, "Unknown", index=str(i), dependencies=str(i))
    for i, known in zip(outputs, structure.output_dependencies):
        ET.SubElement(outs, "Unknown", index=str(i), dependencies=dependencies(known))
    ders = ET.SubElement(element, "Derivatives")
    for i, known in zip(derivatives, structure.derivative_dependencies):
        ET.SubElement(ders, "Unknown", index=str(i), dependencies=dependencies(known))
    initial = ET.SubElement(element, "InitialUnknowns")
    for i in sorted(state_index + derivatives + outputs):
        ET.SubElement(initial, "Unknown", index=str(i))
    ET.indent(root, space="  ")
    text = ET.tostring(root, encoding="unicode")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + text + "\n", every, structure


def _rate_unit(unit: str) -> str:
    """The unit of a rate of a quantity in ``unit``: ``m`` -> ``m/s``, ``m/s`` -> ``m/s^2``, a pure number -> ``1/s``.

    >>> _rate_unit("m"), _rate_unit("m/s"), _rate_unit("m/s^2"), _rate_unit(""), _rate_unit("degC")
    ('m/s', 'm/s^2', 'm/s^3', '1/s', 'K/s')
    """
    if unit == "":
        return "1/s"
    if unit == "degC":  # a rate of a temperature is a difference per second
        return "K/s"
    power = re.fullmatch(r"(.*)/s(?:\^(\d+))?", unit)
    if power and "/" not in power.group(1).replace("/(", "("):
        return f"{power.group(1)}/s^{int(power.group(2) or 1) + 1}"
    return f"{unit}/s"


def _documentation(
    system: System, name: str, step: float, method: str, every: Sequence[Variable], defaults: Sequence[float],
    tunable: Sequence[bool],
) -> str:
    """``documentation/index.html``: what the FMU is, how it steps, and every variable with its unit."""

    def rows(kind: str) -> str:
        lines = []
        for vr, v in enumerate(every):
            if v.kind != kind:
                continue
            cells = [f"<code>{html.escape(v.name)}</code>", str(vr), html.escape(v.unit or "-")]
            if kind == "parameter":
                cells += [f"{defaults[vr]:.6g}", "tunable" if tunable[vr] else "fixed"]
            cells.append(html.escape(v.description))
            lines.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
        return "\n".join(lines)

    head = "<tr><th>name</th><th>value reference</th><th>unit</th>"
    sections = []
    for kind, title in (("parameter", "Parameters"), ("input", "Inputs"), ("state", "States (outputs too)"),
                        ("output", "Outputs")):  # fmt: skip
        if not any(v.kind == kind for v in every):
            continue
        extra = "<th>start</th><th>variability</th>" if kind == "parameter" else ""
        sections.append(
            f"<h2>{title}</h2>\n<table>\n{head}{extra}<th>description</th></tr>\n{rows(kind)}\n</table>"
        )
    title = html.escape(system.name)
    if method in ADAPTIVE_METHODS:
        cosim = (
            f"a variable-step {html.escape(method)} solver with error control inside: any communication step; a "
            "co-simulation starts at t = 0."
        )
    else:
        cosim = (
            f"a fixed-step {html.escape(method)} stepper inside, with the step {step:g} s: a communication step "
            "must be a whole number of those steps, and a co-simulation starts at t = 0."
        )
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{title}</title>
<style>body{{font-family:sans-serif;max-width:70em}} td,th{{padding:2px 8px;text-align:left}}
tr:nth-child(even){{background:#f2f2f2}}</style></head>
<body>
<h1>{title}</h1>
<p>{html.escape(system.description)}</p>
<p>An FMI 2.0 FMU written by hydroservo {__version__} (<code>hydroservo export-fmu</code>), for Model Exchange and
Co-Simulation. Model identifier <code>{name}</code>.</p>
<ul>
<li><b>Model Exchange</b>: the host's integrator steps the model in continuous time. The model has no events.
Use a stiff integrator (BDF, e.g. CVODE) with a relative tolerance of about 1e-6.</li>
<li><b>Co-Simulation</b>: {cosim}</li>
<li>Parameters marked <i>tunable</i> may change between steps (the states keep their values); <i>fixed</i> ones set
only the initial states and are set before the initialisation ends.</li>
<li>An input is added to whatever drives it inside the model (zero: the model as exported).</li>
<li>Units are SI, except temperatures in &deg;C and any the model declares otherwise.</li>
<li><code>sources/</code> builds the binary for another platform: compile the four <code>.c</code> files into a
shared library named <code>{name}</code> with only the C standard library and libm (for instance
<code>cc -O2 -shared -fPIC -o {name}.so *.c -lm</code>).</li>
</ul>
{chr(10).join(sections)}
</body></html>
"""


def _directional(model: Model, n_parameters: int, cid: str) -> ca.Function:
    """``{cid}_fmu_fwd(t, x, p, v) -> (df, dy)``: the rates' and the outputs' derivatives along ``v`` (a change
    of the states, in their units, then of the inputs), exact (CasADi's forward mode), for the FMU's
    ``fmi2GetDirectionalDerivative``; ``p`` is the parameters followed by the inputs."""
    t, x, p = ca.SX.sym("t"), ca.SX.sym("x", model.nx), ca.SX.sym("p", model.np)
    known = ca.vertcat(x, p[n_parameters:])
    v = ca.SX.sym("v", known.numel())
    rates, outputs = model.f(t, x, p), model.outputs(t, x, p)
    return ca.Function(
        f"{cid}_fmu_fwd", [t, x, p, v], [ca.densify(ca.jtimes(rates, known, v)), ca.densify(ca.jtimes(outputs, known, v))]
    )


def _fmu_data(
    cid: str, guid: str, system: System, parameters: Sequence[str], tunable: Sequence[bool], fwd: ca.Function
) -> str:
    """The ``@FMU_DATA@`` block of the FMI interface: GUID, each parameter's tunability and range, and the work
    space of the forward-derivative function ``fwd``."""
    spec = system.declared("PARAMETERS")

    def bound(value: float | None) -> str:
        return "NAN" if value is None or not math.isfinite(value) else repr(float(value))

    def array(ctype: str, what: str, items: Sequence[str]) -> str:
        body = "".join(f"    {item},\n" for item in items) or "    0,\n"
        return f"static const {ctype} {cid}_fmu_{what}[] = {{\n{body}}};\n"

    params = [spec[n] for n in parameters]
    sizes = [f"#define FWD_SZ_{what.upper()} {getattr(fwd, f'sz_{what}')()}" for what in ("arg", "res", "iw", "w")]
    return "\n".join(
        [
            *sizes,
            f'static const char {cid}_fmu_guid[] = "{guid}";',
            array("int", "tunable", [str(int(t)) for t in tunable]),
            array("double", "min", [bound(p.min) for p in params]),
            array("double", "max", [bound(p.max) for p in params]),
            array("int", "min_excluded", [str(int(p.min is not None and not p.min_inclusive)) for p in params]),
            array("int", "max_excluded", [str(int(p.max is not None and not p.max_inclusive)) for p in params]),
        ]
    )


def check_cosimulation_method(method: str, what: str = "method") -> str:
    """``method`` if the FMU can co-simulate with it: a fixed-step stepper (:data:`~hydroservo.codegen.c.METHODS`)
    or a variable-step one (:data:`~hydroservo.codegen.c.ADAPTIVE_METHODS`); ``what`` names it in errors."""
    if method not in (*METHODS, *ADAPTIVE_METHODS):
        raise ParameterError(
            f"{what} {shorten(str(method))!r}: expected one of {', '.join((*METHODS, *ADAPTIVE_METHODS))}"
        )
    return method


def export_fmu(
    system: System,
    directory: str | Path,
    *,
    step: float | str = DEFAULT_STEP,
    method: str = DEFAULT_METHOD,
    inputs: Sequence[str] = (),
    name: str | None = None,
    newton_tolerance: float = NEWTON_TOLERANCE,
    binary: bool = True,
    force: bool = False,
    accuracy: float = DEFAULT_ACCURACY,
) -> FmuExport:
    """Write ``system`` as the FMI 2.0 FMU ``NAME.fmu`` (Model Exchange and Co-Simulation) into ``directory``.

    Parameters
    ----------
    system : System
        The model; its current parameter values are the FMU's start values.
    directory : path
        The folder to write to; a file of the same name is replaced only with ``force``.
    step : float or str
        Co-Simulation: the fixed step [s] of the stepper inside (default 0.1 ms).
    method : "rk4", "bdf2", "rodas3", "ros23" or "dopri5"
        Co-Simulation: the fixed-step stepper's method (default ``rk4``; ``bdf2``, implicit, for stiff circuits),
        or a variable-step method with error control (``rodas3`` or ``ros23`` for stiff circuits, ``dopri5``), which takes any
        communication step and ignores ``step``.
    accuracy : float
        ``rodas3``, ``ros23``, ``dopri5``: the deviation wanted, relative to each signal's range (tolerances as
        :func:`~hydroservo.system.integration.tolerances` sets them for the method; default 1e-4).
    inputs : sequence of str
        Component inputs (``"valve.u"``) the host sets; each is added to what drives it in the system.
    name : str, optional
        The model identifier (a C identifier; default: from the system's name).
    newton_tolerance : float
        ``bdf2``: largest accepted last Newton correction of a state, relative to its nominal magnitude.
    binary : bool
        Build the binary for this machine (needs a C compiler); without, the FMU holds the sources only.
    force : bool
        Replace a file of the same name in ``directory``.

    Raises
    ------
    ParameterError
        As :func:`~hydroservo.codegen.c.export_c` does; also if the file exists (without ``force``).
    ModelError
        If the system has no states, or two of its variables share a name.
    """
    check_cosimulation_method(method)
    h = check_step(step)
    adaptive = method in ADAPTIVE_METHODS
    rtol, atol = tolerances(accuracy, method) if adaptive else tolerances(DEFAULT_ACCURACY)
    cid = c_identifier(system.name) if name is None else check_name(name)
    targets = check_inputs(system, inputs)
    filename = f"{cid}.fmu"
    out = OutputFolder(directory, force=force, what="directory")
    out.expect([filename])
    platform = fmu_platform() if binary else None
    if binary:
        try:
            compiler()
        except ParameterError as exc:
            raise ParameterError(f"{exc}; or write the FMU with its sources alone (--sources-only, binary=False)") from None
    with tempfile.TemporaryDirectory(prefix="hydroservo-fmu-") as tmp:
        build = Path(tmp)
        export = export_c(
            system, build / "sources", step=h, method="rk4" if adaptive else method, inputs=targets, name=cid,
            newton_tolerance=newton_tolerance,
        )  # fmt: skip
        model = Model(assemble(system, perturbed=targets))
        fwd = _directional(model, len(export.parameters), cid)
        generator = ca.CodeGenerator(f"{cid}_fmu_model.c", {"with_header": True, "prefix": f"{cid}_fmu_"})
        generator.add(fwd)
        generator.generate(str(build / "sources") + os.sep)
        sources = [f"{cid}.c", f"{cid}_model.c", f"{cid}_fmu_model.c", f"{cid}_fmi2.c"]
        headers = [f"{cid}.h", f"{cid}_model.h", f"{cid}_fmu_model.h"]
        placeholder = "{00000000-0000-0000-0000-000000000000}"
        description, every, structure = model_description(
            system, model, name=cid, guid=placeholder, step=h, inputs=targets, sources=sources
        )
        digest = hashlib.sha256(description.encode())
        for source in [f"{cid}.c", f"{cid}_model.c", f"{cid}_fmu_model.c", *headers]:
            digest.update((build / "sources" / source).read_bytes())
        digest.update(c_template("fmi2.c").encode())
        guid = "{" + str(uuid.UUID(bytes=digest.digest()[:16], version=5)) + "}"
        description = description.replace(placeholder, guid)
        data = _fmu_data(cid, guid, system, export.parameters, structure.tunable, fwd)
        values = {"NAME": cid, "UPPER": cid.upper(), "MODEL": _c_comment(system.name),
                  "VERSION": __version__, "METHOD": method, "STEP": repr(h), "FMU_DATA": data,
                  "FMU_ADAPTIVE": str(ADAPTIVE_METHODS.index(method) + 1 if adaptive else 0),
                  "FMU_RTOL": repr(rtol), "FMU_ATOL": repr(atol)}  # fmt: skip
        interface = fill_template("fmi2.c", values)
        (build / "sources" / f"{cid}_fmi2.c").write_text(interface, encoding="utf-8")
        members: dict[str, Path] = {"modelDescription.xml": build / "modelDescription.xml"}
        (build / "modelDescription.xml").write_text(description, encoding="utf-8")
        for source in [*sources, *headers]:
            members[f"sources/{source}"] = build / "sources" / source
        (build / "index.html").write_text(
            _documentation(system, cid, h, method, every, export.defaults, structure.tunable), encoding="utf-8"
        )
        members["documentation/index.html"] = build / "index.html"
        if platform is not None:
            library = cid + library_suffix()
            compile_library(build / "sources", sources, library, flags=("-O2", "-fvisibility=hidden"))
            members[f"binaries/{platform}/{library}"] = build / "sources" / library
        with out:
            with zipfile.ZipFile(out.file(filename), "w", compression=zipfile.ZIP_DEFLATED) as archive:
                for arcname, path in members.items():
                    info = zipfile.ZipInfo(arcname, date_time=(2020, 1, 1, 0, 0, 0))  # reproducible archives
                    info.compress_type = zipfile.ZIP_DEFLATED
                    info.external_attr = 0o644 << 16
                    archive.writestr(info, path.read_bytes())
    return FmuExport(
        path=Path(directory) / filename,
        name=cid,
        model=system.name,
        guid=guid,
        step=h,
        method=method,
        variables=tuple(every),
        defaults=export.defaults,
        tunable=structure.tunable,
        platform=platform,
        files=tuple(members),
    )
