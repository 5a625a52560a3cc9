"""Algebraic unknowns, solved by Newton's method written into the model's expression graph.

A component may declare unknowns that no rate defines (``ALGEBRAIC``), each
with a residual that vanishes at its solution and an explicit first guess:
the flapper tip of a servovalve, bent by the jets whose force depends on the
tip ([GordicND] eqs. 13-14), or the pressure of a junction without volume.
The system gathers them into one vector :math:`z` with residual
:math:`r(t, x, z, p) = 0` and solves it, inside the expression graph, by a
fixed number of Newton steps from the guesses, with the exact Jacobian
:math:`\\partial r/\\partial z`:

.. math:: z_{k+1} = z_k - \\left(\\frac{\\partial r}{\\partial z}(z_k)\\right)^{-1} r(z_k).

The model is then an ordinary ODE in the states again: every solver,
linearisation, batch map and code generator of the engine works on it
unchanged. Its derivatives are exact at convergence: the derivative of the
last Newton step with respect to the states is
:math:`-r_z^{-1} r_x`, the implicit function theorem's, up to terms in the
residual itself.

A fixed number of steps is a promise to check, so the model keeps the size of
the last Newton correction, relative to each unknown's nominal magnitude;
every run checks it at every output time and fails, naming the unknown, the
time and the size, if it exceeds :data:`TOLERANCE` (Newton converges
quadratically: a correction of 1e-9 leaves an error near 1e-18).

Why not CasADi's rootfinder, or a DAE for IDAS? Both were measured on a
stiff ODE of six states with one implicit unknown
(``benchmarks/bench_implicit.py``): the three agree to 7e-7 at rtol 1e-10;
the rootfinder, which needs the slower MX expression graph throughout, runs
4 to 5 times slower than unrolled Newton; IDAS is 1.2 times slower and would
give the engine a second kind of model (algebraic states in every solver,
trim, linearisation, frequency response and code generator).
docs/engine.md records the figures.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import casadi as ca
import numpy as np

from hydroservo.errors import ModelError

__all__ = ["NEWTON_STEPS", "TOLERANCE", "newton"]

#: Newton steps taken from the guess (the last of them is measured: see :func:`newton`).
NEWTON_STEPS = 8

#: Largest accepted last Newton correction, relative to the unknown's nominal magnitude.
TOLERANCE = 1e-9


def newton(
    z: Any, residual: Any, guess: Any, nominal: Sequence[float], names: Sequence[str], steps: int = NEWTON_STEPS
) -> tuple[Any, Any]:
    """The unknowns ``z`` after ``steps`` Newton steps on ``residual`` from ``guess``, and the last correction.

    Parameters
    ----------
    z : casadi.SX
        Column of the unknowns' symbols.
    residual, guess : casadi.SX
        Columns as long as ``z``: the residuals (functions of ``z`` and of other symbols) and the first guesses
        (which must not depend on ``z``).
    nominal : sequence of float
        Typical magnitude of each unknown; the returned correction is divided by it.
    names : sequence of str
        The unknowns' names, for messages.

    Returns
    -------
    (solution, correction)
        Expressions of the other symbols: the unknowns, and the absolute value of the last Newton step taken
        (relative to ``nominal``).
    """
    n = z.numel()
    for k in range(n):
        if ca.depends_on(guess[k], z):
            raise ModelError(
                f"the first guess of the algebraic unknown {names[k]} depends on algebraic unknowns; "
                "a guess must be explicit (states, inputs that do not read unknowns, parameters)"
            )
    jac = ca.jacobian(residual, z)
    for k in range(n):
        if not ca.depends_on(residual, z[k]):
            raise ModelError(f"no residual depends on the algebraic unknown {names[k]}: it cannot be solved for")
    nom = ca.DM(np.asarray(nominal, dtype=float))
    zk = guess
    step = ca.SX.zeros(n)
    for _ in range(steps):
        r, J = ca.substitute([residual, jac], [z], [zk])
        step = r / J if n == 1 else ca.solve(J, r)
        zk = zk - step
    return zk, ca.fabs(step) / nom
