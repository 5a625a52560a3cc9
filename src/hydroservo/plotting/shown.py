"""The figures pyplot shows (a plot given no file): a notebook shows each once.

IPython shows a cell's last value by its formatters, and matplotlib's inline backend shows every figure pyplot
holds as the cell ends: a figure returned by the cell's last line (``result.plot()``) would be shown twice. A
:class:`ShownFigure` shows itself once per cell. Imported only when a figure is shown, so that matplotlib is
imported only to draw.
"""

from __future__ import annotations

from typing import Any

import matplotlib
from matplotlib._pylab_helpers import Gcf
from matplotlib.figure import Figure

__all__ = ["ShownFigure"]


class ShownFigure(Figure):
    """A figure of pyplot's that IPython shows at most once per cell: as the cell's last value, or as the inline
    backend shows the figures it holds when the cell ends, whichever comes first; again in a later cell that
    shows it. Where pyplot holds it on another backend (a window, a widget), that backend shows it."""

    _shown_in: Any = None  #: the cell (IPython's execution count) that showed the figure

    def _ipython_display_(self) -> None:
        from IPython import get_ipython
        from IPython.core.pylabtools import print_figure
        from IPython.display import display

        manager = getattr(self.canvas, "manager", None)
        held = manager is not None and Gcf.get_fig_manager(manager.num) is manager
        if held and "inline" not in matplotlib.get_backend():
            return
        shell = get_ipython()
        cell = getattr(shell, "execution_count", None)
        if cell is not None and cell == self._shown_in:
            return
        self._shown_in = cell
        display({"image/png": print_figure(self, "png", bbox_inches="tight"), "text/plain": repr(self)}, raw=True)
