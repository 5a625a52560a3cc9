"""Plots an engineer would rather look at than read: results, Bode plots, valve characteristics.

Every function draws into a new figure, saves it when ``file`` is given
(without needing a display) and returns the figure. Matplotlib is imported
only when a plot is drawn.

=====================  ==========================================================
module                 plots
=====================  ==========================================================
:mod:`.results`        signals of a simulation against time
:mod:`.bode`           amplitude-dependent Bode plots, data against models
:mod:`.pseudo_section` pseudo-sections and the characteristics of a
                       pseudo-section valve ([FerreiraND] Figs. 2-9)
:mod:`.staged_slot`    test-bench characteristics of the staged-slot valve
                       across temperature ([MareAttarND] Figs. 3-4, 6-8)
:mod:`.study`          parameter studies: a family of responses coloured by a
                       parameter, metrics against a parameter
:mod:`.linear`         linear models: the poles with their modes, Bode plots of
                       input-output pairs
=====================  ==========================================================
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["pyplot", "finish", "lpm"]


def pyplot(file: str | Path | None) -> Any:
    """``matplotlib.pyplot``, with a file backend when the figure goes to ``file``."""
    import matplotlib

    if file is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def finish(fig: Any, file: str | Path | None, plt: Any) -> Any:
    """Lay out ``fig``, save it to ``file`` (and close it) when given; return it."""
    fig.tight_layout()
    if file is not None:
        fig.savefig(file, dpi=110)
        plt.close(fig)
    return fig


def lpm(q: Any) -> Any:
    """Flows [m^3/s] in L/min."""
    return np.asarray(q) * 6e4
