"""Fluid properties against temperature and pressure (``hydroservo fluid``).

>>> from hydroservo.workflows import fluid
>>> report = fluid.run("density", fluid="skydrol", temperature="20", pressure="0,30 MPa")
>>> [round(r["density"]) for r in report.to_dict()["values"]]
[1008, 1028]
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.errors import ParameterError
from hydroservo.workflows.base import Progress, Report, Workflow

if TYPE_CHECKING:
    import numpy as np

    from hydroservo.fluids import Fluid
    from hydroservo.io.html import Page

__all__ = ["FluidProperties", "FluidReport", "run", "SHOWN"]

#: Display units of each property.
SHOWN = {
    "density": "kg/m^3",
    "specific_volume": "L/kg",
    "kinematic_viscosity": "cSt",
    "dynamic_viscosity": "mPa*s",
    "bulk_modulus": "MPa",
}


def values_of(text: str | Sequence[float], unit: str, what: str) -> list[float]:
    """Comma-separated values; a unit written once at the end applies to all bare numbers (``"0,10,30 MPa"``).
    Temperatures (``unit`` degC) come back in degC, other values in SI; a sequence of numbers is taken as it is."""
    from hydroservo.units import parse_quantity, to_si

    if not isinstance(text, str):
        return [float(v) for v in text]
    items = [t.strip() for t in text.split(",") if t.strip()]
    if not items:
        raise ParameterError(f"{what} {text!r}: expected comma-separated values, e.g. '-40,20,70' or '0,30 MPa'")
    trailing = unit
    last = items[-1].split(maxsplit=1)
    if len(last) == 2:
        trailing = last[1]
    out = []
    for item in items:
        q = item if len(item.split(maxsplit=1)) == 2 else f"{item} {trailing}"
        try:
            if unit == "degC":
                out.append(float(parse_quantity(q, what=what).to("degC").magnitude))
            else:
                out.append(to_si(q, unit, what=what))
        except ParameterError:
            raise
        except Exception as exc:  # pint: dimensionality, parsing
            raise ParameterError(f"{what} {item!r}: {exc}") from None
    return out


@dataclass
class FluidReport(Report):
    """The properties at every temperature and pressure, in display units (:data:`SHOWN`)."""

    command: ClassVar[str] = "fluid"

    fluid: Fluid
    properties: list[str]
    temperatures: list[float]  #: [degC]
    pressures: list[float]  #: gauge [Pa]
    shown: dict[str, np.ndarray]  #: property -> values in its display unit, [temperature, pressure]
    notes: list[str] = field(default_factory=list)  #: the fluid model's range warnings

    def title(self) -> str:
        return f"{self.fluid.name}: {self.fluid.description}"

    def to_dict(self) -> dict[str, Any]:
        rows: list[dict[str, Any]] = []
        for i, t in enumerate(self.temperatures):
            for j, pr in enumerate(self.pressures):
                rows.append({"temperature_degC": t, "pressure_Pa": pr,
                             **{p: float(self.shown[p][i, j]) for p in self.properties}})
        return {
            "fluid": self.fluid.name,
            "description": self.fluid.description,
            "units": {p: SHOWN[p] for p in self.properties},
            "values": rows,
            "warnings": self.notes,
        }

    def lines(self) -> list[str]:
        out = [self.title()]
        head = ["T [degC]", "p [MPa]"] + [f"{p} [{SHOWN[p]}]" for p in self.properties]
        out.append("  ".join(f"{h:>14}" for h in head))
        for i, t in enumerate(self.temperatures):
            for j, pr in enumerate(self.pressures):
                cells = [f"{t:>14g}", f"{pr / 1e6:>14g}"] + [f"{self.shown[p][i, j]:>14.5g}" for p in self.properties]
                out.append("  ".join(cells))
        out += [f"warning: {w}" for w in self.notes]
        return out

    def document(self) -> Page:
        """The properties at every temperature and pressure, and each against temperature (interactive)."""
        import numpy as np

        from hydroservo.io.html import Figure, Notice, Section, Table
        from hydroservo.plotting.interactive import xy_figure
        from hydroservo.workflows import pages

        rows = [[t, p / 1e6, *(float(self.shown[q][i, j]) for q in self.properties)]
                for i, t in enumerate(self.temperatures) for j, p in enumerate(self.pressures)]
        table = Table(["T [degC]", "p [MPa]", *(f"{q} [{SHOWN[q]}]" for q in self.properties)], rows)
        figures = []
        if len(self.temperatures) > 1:
            for q in self.properties:
                curves = [(np.array(self.temperatures), self.shown[q][:, j], f"{p / 1e6:g} MPa")
                          for j, p in enumerate(self.pressures)]
                figures.append(Figure(xy_figure(curves, "T [degC]", f"{q} [{SHOWN[q]}]", title=q)))
        return pages.page(self.title(), "fluid properties", [
            Section("Properties", [table, *(Notice(n) for n in self.notes)]),
            Section("Against temperature", figures) if figures else None,
        ], self.warnings)


@dataclass
class FluidProperties(Workflow):
    """``property`` (one of :data:`hydroservo.fluids.PROPERTIES` or ``"all"``) of a built-in fluid.

    ``temperature`` and ``pressure`` are comma-separated values (bare numbers in degC and Pa, or a unit once at
    the end: ``"0,10,30 MPa"``) or sequences of numbers (degC; Pa gauge). ``strict`` refuses values outside the
    fluid model's range (otherwise a warning).
    """

    property: str
    fluid: str = "skydrol"
    temperature: str | Sequence[float] = "20"
    pressure: str | Sequence[float] = "0"
    strict: bool = False

    def __post_init__(self) -> None:
        from hydroservo.fluids import PROPERTIES, get_fluid

        self.model = get_fluid(self.fluid)
        self.properties = list(PROPERTIES) if self.property == "all" else [self.property.replace("-", "_")]
        for p in self.properties:
            if p not in PROPERTIES:
                raise ParameterError(f"property {self.property!r}: expected one of {', '.join(PROPERTIES)} or all")
        self.temperatures = values_of(self.temperature, "degC", self.name("temperature"))
        self.pressures = values_of(self.pressure, "Pa", self.name("pressure"))

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> FluidReport:
        import numpy as np

        from hydroservo.fluids import PROPERTIES
        from hydroservo.units import from_si

        fluid, temps, press = self.model, self.temperatures, self.pressures
        T, P = np.meshgrid(temps, press, indexing="ij")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                fluid.check_range(P, T, strict=self.strict)
            except ParameterError as exc:
                raise ParameterError(
                    f"{self.name('temperature')} {self._shown(self.temperature)!r}, "
                    f"{self.name('pressure')} {self._shown(self.pressure)!r}: {exc}"
                ) from None
        with np.errstate(all="ignore"):
            values = {p: np.asarray(getattr(fluid, p)(P, T), dtype=float) for p in self.properties}
        for p in self.properties:
            bad = ~np.isfinite(values[p]) | (values[p] <= 0)
            if bad.any():
                i, j = np.argwhere(bad)[0]
                raise ParameterError(
                    f"fluid {fluid.name!r}: no physical {p.replace('_', ' ')} at {temps[i]:g} degC and {press[j]:g} Pa "
                    f"(the model gives {values[p][i, j]:g}); {self.name('temperature')} and {self.name('pressure')} "
                    "are far outside its range"
                )
        shown = {p: values[p] * from_si(1.0, PROPERTIES[p], SHOWN[p]) for p in self.properties}
        return FluidReport(fluid, self.properties, temps, press, shown, [str(w.message) for w in caught])

    @staticmethod
    def _shown(value: str | Sequence[float]) -> str:
        return value if isinstance(value, str) else ",".join(f"{v:g}" for v in value)


def run(property: str, **inputs: Any) -> FluidReport:
    """``property`` of a fluid (:class:`FluidProperties`'s inputs as keywords)."""
    return FluidProperties(property, **inputs).run()
