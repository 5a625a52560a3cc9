"""Three ways to simulate an ODE with an algebraic unknown, timed against each other in this process.

Run: ``python benchmarks/bench_implicit.py``

The model: a chain of three damped oscillators (6 states) whose first one is
pulled towards an unknown :math:`z` defined implicitly by
:math:`z + c \\tanh(z/0.5)(1 + z^2) = x_1` (a loop as nonlinear as the
servovalve's flapper tip, eqs. 13-14 of [GordicND]), driven at 10 Hz for one
second. The same equations are solved

1. by Newton's method unrolled in the SX expression graph, from an explicit
   guess (what hydroservo does: :mod:`hydroservo.system.implicit`), with CVODES;
2. by CasADi's Newton rootfinder called inside an MX expression graph, with
   CVODES;
3. as a semi-explicit DAE with IDAS.

Printed: the median CPU time of each over repeats (steadier than wall time on a shared machine), as a ratio to the first,
and the largest difference of each solution from the first at tight
tolerance (all three must agree). Written to benchmarks/results/implicit.json.
"""

from __future__ import annotations

import statistics
import time

import casadi as ca
import numpy as np
from results import record

NX = 6
W = 2 * np.pi * 50
GRID = np.linspace(0.0, 1.0, 1001)


def rhs(t, x, z, p):  # type: ignore[no-untyped-def]
    f = [x[1], -(W**2) * (x[0] - z) - 2 * 0.3 * W * x[1] + W**2 * ca.sin(2 * np.pi * 10 * t) * p[0]]
    for k in range(2, NX, 2):
        f += [x[k + 1], -(W**2) * (x[k] - x[k - 2]) - 2 * 0.5 * W * x[k + 1]]
    return ca.vertcat(*f)


def residual(z, x, p):  # type: ignore[no-untyped-def]
    return z + p[1] * ca.tanh(z / 0.5) * (1 + z**2) - x[0]


def guess(x, p):  # type: ignore[no-untyped-def]
    return x[0] / (1 + 2 * p[1])


def integrators(tol: float) -> dict[str, tuple[ca.Function, dict]]:
    opts = {"abstol": tol * 1e-2, "reltol": tol}
    t, x, p, z = ca.SX.sym("t"), ca.SX.sym("x", NX), ca.SX.sym("p", 2), ca.SX.sym("z")
    out = {}
    # 1. unrolled Newton
    zk = guess(x, p)
    dr = ca.jacobian(residual(z, x, p), z)
    for _ in range(8):
        zk = zk - ca.substitute(residual(z, x, p) / dr, z, zk)
    out["unrolled Newton (SX)"] = (
        ca.integrator("a", "cvodes", {"t": t, "x": x, "p": p, "ode": rhs(t, x, zk, p)}, 0.0, list(GRID), opts),
        {},
    )
    # 2. rootfinder in MX
    g = ca.Function("g", [z, ca.vertcat(t, x, p)], [residual(z, x, p)])
    G = ca.rootfinder("G", "newton", g, {"abstol": 1e-14})
    tm, xm, pm = ca.MX.sym("t"), ca.MX.sym("x", NX), ca.MX.sym("p", 2)
    zm = G(guess(xm, pm), ca.vertcat(tm, xm, pm))
    f = ca.Function("f", [t, x, z, p], [rhs(t, x, z, p)])
    dae = {"t": tm, "x": xm, "p": pm, "ode": f(tm, xm, zm, pm)}
    out["rootfinder (MX)"] = (ca.integrator("b", "cvodes", dae, 0.0, list(GRID), opts), {})
    # 3. IDAS
    dae = {"t": t, "x": x, "z": z, "p": p, "ode": rhs(t, x, z, p), "alg": residual(z, x, p)}
    out["DAE (IDAS)"] = (ca.integrator("c", "idas", dae, 0.0, list(GRID), opts), {"z0": 0.0})
    return out


#: the figures' keys of each method (benchmarks/results/implicit.json)
KEYS = ("newton", "rootfinder", "idas")


def main(repeat: int = 7) -> None:
    p = [1.0, 0.6]
    figures: dict[str, float] = {}
    print(f"{'method':<24}{'median [ms]':>12}{'ratio':>8}{'steps':>8}{'max diff':>12}")
    for tol in (1e-6, 1e-10):
        print(f"rtol = {tol:g}")
        base = ref = None
        for key, (name, (integ, extra)) in zip(KEYS, integrators(tol).items(), strict=True):
            times = []
            for _ in range(repeat):
                start = time.process_time()
                res = integ(x0=np.zeros(NX), p=p, **extra)
                times.append(time.process_time() - start)
            med = statistics.median(times) * 1e3
            X = np.asarray(res["xf"])
            base = med if base is None else base
            ref = X if ref is None else ref
            diff = float(np.abs(X - ref).max())
            print(f"{name:<24}{med:>12.2f}{med / base:>8.2f}{integ.stats()['nsteps']:>8}{diff:>12.2e}")
            figures[f"{key}_{tol:.0e}_ms"], figures[f"{key}_{tol:.0e}_ratio"] = med, med / base
            figures[f"{key}_{tol:.0e}_diff"] = diff
    record("implicit", figures)


if __name__ == "__main__":
    main()
