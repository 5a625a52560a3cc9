"""Plots an engineer would rather look at than read: results, Bode plots, valve characteristics.

Every function draws into a new figure, saves it when ``file`` is given
(without needing a display) and returns the figure. Matplotlib is imported
only when a plot is drawn.

======================  ==========================================================
module                  plots
======================  ==========================================================
:mod:`.results`         signals of a simulation against time
:mod:`.bode`            amplitude-dependent Bode plots, data against models
:mod:`.pseudo_section`  pseudo-sections and the characteristics of a
                        pseudo-section valve ([FerreiraND] Figs. 2-9)
:mod:`.staged_slot`     test-bench characteristics of the staged-slot valve
                        across temperature ([MareAttarND] Figs. 3-4, 6-8)
:mod:`.study`           parameter studies: a family of responses coloured by a
                        parameter, metrics against a parameter
:mod:`.linear`          linear models: the poles with their modes, Bode plots of
                        input-output pairs
======================  ==========================================================
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["pyplot", "finish", "lpm", "panel_units", "by_dimension", "axis_label", "curve_label"]


def pyplot(file: Any) -> Any:
    """What a plot draws with: ``subplots``, ``rcParams``, ``get_cmap``, ``cm``, ``Rectangle``, ``close``.

    A figure that goes to ``file`` is a plain :class:`matplotlib.figure.Figure`, drawn and written without pyplot:
    matplotlib's backend is never chosen or changed (a notebook's stays its own), and pyplot, which would show
    the figure again at the end of a notebook's cell, never holds it. A figure to be shown (``file`` None) is
    pyplot's, on the backend in use, a :class:`~hydroservo.plotting.shown.ShownFigure`, which a notebook shows
    once."""
    if file is not None:
        return _FileFigures()
    import matplotlib.pyplot as plt

    return _ShownFigures(plt)


class _FileFigures:
    """The parts of pyplot the plots use, for figures written to a file: pyplot is not imported."""

    def subplots(self, nrows: int = 1, ncols: int = 1, *, figsize: Any = None, dpi: Any = None, **kwargs: Any) -> Any:
        from matplotlib.figure import Figure

        fig = Figure(figsize=figsize, dpi=dpi)
        return fig, fig.subplots(nrows, ncols, **kwargs)

    def close(self, fig: Any) -> None:
        """Nothing to close: no backend holds the figure."""

    def get_cmap(self, name: str) -> Any:
        import matplotlib

        return matplotlib.colormaps[name]

    def __getattr__(self, name: str) -> Any:
        import matplotlib
        import matplotlib.cm
        import matplotlib.patches

        found = {"rcParams": lambda: matplotlib.rcParams, "cm": lambda: matplotlib.cm,
                 "Rectangle": lambda: matplotlib.patches.Rectangle}.get(name)
        if found is None:
            raise AttributeError(f"pyplot's {name!r} is not offered for a figure written to a file")
        return found()


class _ShownFigures:
    """pyplot, its figures made as :class:`~hydroservo.plotting.shown.ShownFigure`."""

    def __init__(self, plt: Any) -> None:
        self._plt = plt

    def subplots(self, *args: Any, **kwargs: Any) -> Any:
        from hydroservo.plotting.shown import ShownFigure

        return self._plt.subplots(*args, FigureClass=ShownFigure, **kwargs)

    def __getattr__(self, name: str) -> Any:
        return getattr(self._plt, name)


def finish(fig: Any, file: Any, plt: Any, show: bool | None = False) -> Any:
    """Lay out ``fig``, save it to ``file`` (a path or a binary file; and close it) when given; return it.

    ``show=None`` (what :meth:`Result.plot <hydroservo.system.result.Result.plot>` passes) shows a figure that
    goes to no file where it can be seen: a notebook shows it by itself, a window backend (a script run with a
    display) opens it with ``plt.show()``; with neither (Agg, no display), a warning says to give ``file``."""
    title = getattr(fig, "_suptitle", None)  # kept clear of the axes below it, whatever the figure's height
    fig.tight_layout(rect=(0.0, 0.0, 1.0, 1.0 - 0.3 / fig.get_figheight() if title is not None else 1.0))
    if file is not None:
        fig.savefig(file, dpi=110)
        plt.close(fig)
    elif show is None:
        _show(plt)
    return fig


def _show(plt: Any) -> None:
    import warnings

    import matplotlib

    backend = matplotlib.get_backend().lower()
    if "inline" in backend or "ipympl" in backend or "widget" in backend or "nbagg" in backend:
        return  # the notebook shows the figure itself
    if backend in ("agg", "pdf", "ps", "svg", "cairo", "template", "pgf"):
        warnings.warn(
            f"the figure is not shown: matplotlib's backend {backend!r} has no display; give file='plot.png' to "
            "write it, or run where a display is",
            UserWarning, stacklevel=4,
        )
        return
    plt.show()


def panel_units(own: dict[str, str], panel: list[str], units: dict[str, str]) -> list[str]:
    """The unit each signal of a plot panel is drawn in: the first signal's (its unit in ``units``, else its own
    ``own`` unit) for every signal of that dimension, so that one axis has one unit; a signal of another
    dimension keeps its own choice.

    >>> panel_units({"a": "Pa", "b": "Pa", "c": "m"}, ["a", "b", "c"], {"a": "psi", "b": "bar"})
    ['psi', 'psi', 'm']
    """
    from hydroservo.units import same_dimension

    first = units.get(panel[0]) or own.get(panel[0], "")
    out = []
    for name in panel:
        mine = units.get(name) or own.get(name, "")
        out.append(first if mine != first and own.get(name, "") and same_dimension(first, mine) else mine)
    return out


def by_dimension(panels: Any, units: dict[str, str]) -> list[list[str]]:
    """Plot panels with one dimension each: a panel whose signals have several (a Hopsan scope of pressures and
    flows) becomes one panel per dimension, in the order they first appear; a panel repeated is drawn once.

    >>> by_dimension([["p1", "q1", "p2"], ["x"], ["p1", "q1", "p2"]], {"p1": "Pa", "p2": "bar", "q1": "m^3/s", "x": "m"})
    [['p1', 'p2'], ['q1'], ['x']]
    """
    from hydroservo.units import same_dimension

    out: list[list[str]] = []
    for panel in panels:
        groups: list[list[str]] = []
        for name in panel:
            unit = units.get(name, "")
            home = next((g for g in groups if same_dimension(units.get(g[0], ""), unit)), None)
            if home is None:
                groups.append([name])
            else:
                home.append(name)
        out += [g for g in groups if g not in out]
    return out


#: The longest list of names an axis is labelled with; past it, what the signals are (the legend names them).
_LABEL_CHARS = 28


def curve_label(name: str, descriptions: dict[str, str]) -> str:
    """``"name: description"``, or the name alone where the description only spells it again (an imported
    Hopsan variable's ``"Hopsan's Mass#P2#Position"``)."""
    import re

    described = descriptions.get(name, "")
    letters = re.sub(r"\W|_", "", name)
    return name if not described or letters in re.sub(r"\W|_", "", described) else f"{name}: {described}"


def axis_label(panel: list[str], descriptions: dict[str, str], unit: str, drawn: str | None = None) -> str:
    """``"p1, p2 [Pa]"``; for a panel whose names would not fit beside the axis, what its signals have in common
    (``"pressure [Pa]"``: their description, else the quantity of ``drawn``, the unit they are drawn in) or how
    many they are: the legend names them."""
    import textwrap

    names = ", ".join(panel)
    if len(f"{names} [{unit}]") > _LABEL_CHARS:
        described = {descriptions.get(n, "") for n in panel}
        common = described.pop() if len(panel) > 1 and len(described) == 1 and "" not in described else None
        quantity = _quantity(unit if drawn is None else drawn)
        names = common or quantity or (f"{len(panel)} signals" if len(panel) > 1 else "signal")
    return textwrap.fill(f"{names} [{unit}]", _LABEL_CHARS)


#: Quantities an axis may be labelled by, the first of a dimension naming it
_QUANTITY_NAMES = ("pressure", "position", "velocity", "acceleration", "flow", "force", "volume", "area", "mass",
                   "torque", "angle", "speed", "current", "voltage", "power")


def _quantity(unit: str) -> str | None:
    """The name of the quantity ``unit`` measures (``"pressure"`` for bar), if it is one of :data:`_QUANTITY_NAMES`."""
    from hydroservo.units import QUANTITIES, same_dimension

    if not unit or unit == "-":
        return None
    try:
        return next((name for name in _QUANTITY_NAMES if same_dimension(QUANTITIES[name], unit)), None)
    except Exception:  # a unit pint does not know: no quantity
        return None


def lpm(q: Any) -> Any:
    """Flows [m^3/s] in L/min."""
    return np.asarray(q) * 6e4
