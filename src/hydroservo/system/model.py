"""A built model: CasADi functions of one ODE, and the solvers that run it.

This is the only module that knows about integrators. States are integrated
in scaled form, :math:`z = x / x_{nom}`, where every component declares the
nominal magnitude of its states; so one scalar absolute tolerance means the
same thing for a pressure of 1e7 Pa and a spool position of 1e-5 m.
"""

from __future__ import annotations

import os
import time
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from hydroservo.errors import ParameterError, SolverError, TrimError
from hydroservo.system.result import BatchResult, Result
from hydroservo.units import si_unit

__all__ = ["Model"]

_REASONS = {
    "CV_TOO_MUCH_WORK": "the step limit was reached (very stiff dynamics or a diverging state; raise max_steps)",
    "CV_CONV_FAILURE": "the Newton corrector did not converge (a discontinuity or a singular Jacobian)",
    "CV_ERR_FAILURE": "the error test failed repeatedly (a discontinuity or a state blowing up)",
    "CV_TOO_CLOSE": "the output times are too close together",
    "CV_RHSFUNC_FAIL": "the right-hand side could not be evaluated (NaN or Inf)",
    "CV_REPTD_RHSFUNC_ERR": "the right-hand side repeatedly gave NaN or Inf",
}


class Model:
    """Compiled ODE of a :class:`~hydroservo.system.system.System`.

    Attributes
    ----------
    state_names, parameter_names, output_names : list of str
        Order of the state, parameter and output vectors.
    units : dict
        Unit of every state and output.
    f : casadi.Function
        ``f(t, x, p) -> dx/dt`` (SI).
    """

    def __init__(
        self,
        name: str,
        t: ca.SX,
        x: ca.SX,
        p: ca.SX,
        f: ca.SX,
        y: ca.SX,
        x0: ca.SX,
        state_names: list[str],
        parameter_names: list[str],
        output_names: list[str],
        units: dict[str, str],
        descriptions: dict[str, str],
        nominal: np.ndarray,
        parameter_units: dict[str, str],
    ) -> None:
        self.name = name
        self.state_names = state_names
        self.parameter_names = parameter_names
        self.output_names = output_names
        self.units = units
        self.descriptions = descriptions
        self.parameter_units = parameter_units
        self.nominal = np.where(nominal > 0, nominal, 1.0)
        self.nx, self.np = len(state_names), len(parameter_names)
        self.f = ca.Function("f", [t, x, p], [f], ["t", "x", "p"], ["xdot"])
        self.jac_x = ca.Function("jac_x", [t, x, p], [ca.jacobian(f, x)], ["t", "x", "p"], ["A"])
        self.outputs = ca.Function("y", [t, x, p], [y], ["t", "x", "p"], ["y"])
        self.x0 = ca.Function("x0", [p], [x0], ["p"], ["x0"])
        z = ca.SX.sym("z", self.nx)
        nom = ca.DM(self.nominal)
        fz = ca.substitute(f, x, z * nom) / nom
        self._dae = {"x": z, "t": t, "p": p, "ode": fz}
        self._fz = ca.Function("fz", [t, z, p], [fz])
        self._jz = ca.Function("jz", [t, z, p], [ca.jacobian(fz, z)])
        self._integrators: dict[Any, ca.Function] = {}
        self._maps: dict[int, ca.Function] = {}

    # -- helpers -----------------------------------------------------------
    def _integrator(self, grid: np.ndarray, rtol: float, atol: float, max_steps: int) -> ca.Function:
        key = (grid.tobytes(), rtol, atol, max_steps)
        if key not in self._integrators:
            if len(self._integrators) > 16:
                self._integrators.clear()
            opts = {"abstol": atol, "reltol": rtol, "max_num_steps": max_steps, "disable_internal_warnings": True}
            self._integrators[key] = ca.integrator(
                "sim", "cvodes", self._dae, float(grid[0]), [float(g) for g in grid], opts
            )
        return self._integrators[key]

    @staticmethod
    def _grid(t_end: float, t_eval: Sequence[float] | None, n_points: int) -> np.ndarray:
        if t_eval is not None:
            grid = np.asarray(t_eval, dtype=float).ravel()
            if grid.size < 2 or np.any(np.diff(grid) <= 0):
                raise ParameterError("t_eval: expected at least two strictly increasing times [s]")
            return grid
        if not (t_end > 0 and np.isfinite(t_end)):
            raise ParameterError(f"t_end = {t_end!r} s: expected a positive, finite duration")
        if n_points < 2:
            raise ParameterError(f"n_points = {n_points}: expected at least 2")
        return np.linspace(0.0, t_end, int(n_points))

    def initial_state(
        self, p: np.ndarray, initial: str | Mapping[str, float] = "parameters", t0: float = 0.0
    ) -> np.ndarray:
        """Initial state: from the parameters, from an equilibrium (``"trim"``),
        or the parameter-based one with some states overridden (mapping, SI)."""
        if isinstance(initial, str):
            if initial == "trim":
                trim = self.trim(p, t=t0)
                return np.array([trim[n] for n in self.state_names])
            if initial != "parameters":
                raise ParameterError(
                    f"initial = {initial!r}: expected 'parameters', 'trim' or a mapping state -> value"
                )
            return np.asarray(self.x0(p), dtype=float).ravel()
        x0 = np.asarray(self.x0(p), dtype=float).ravel()
        for name, val in initial.items():
            if name not in self.state_names:
                raise ParameterError(f"initial: {name!r} is not a state; states: {', '.join(self.state_names)}")
            x0[self.state_names.index(name)] = float(val)
        return x0

    # -- simulation ----------------------------------------------------------
    def simulate(
        self,
        t_end: float,
        p: np.ndarray,
        *,
        t_eval: Sequence[float] | None = None,
        n_points: int = 1001,
        rtol: float = 1e-6,
        atol: float = 1e-8,
        max_steps: int = 100_000,
        initial: str | Mapping[str, float] = "parameters",
    ) -> Result:
        """Integrate with CVODES (BDF, Newton with the exact Jacobian).

        Parameters
        ----------
        t_end : float
            Duration [s] (ignored when ``t_eval`` is given).
        p : array
            Parameter vector (SI) in the order of :attr:`parameter_names`.
        t_eval : sequence of float, optional
            Output times [s]; the first is the initial time.
        n_points : int
            Number of equally spaced output times when ``t_eval`` is not given.
        rtol, atol : float
            Relative tolerance, and absolute tolerance on states scaled by their
            nominal magnitude.
        initial : "parameters", "trim" or mapping
            Initial state, see :meth:`initial_state`.

        Raises
        ------
        SolverError
            If the integrator fails; the message gives the time, the state and the reason.
        """
        grid = self._grid(t_end, t_eval, n_points)
        p = np.asarray(p, dtype=float)
        x0 = self.initial_state(p, initial, t0=float(grid[0]))
        if not np.all(np.isfinite(x0)):
            bad = [n for n, v in zip(self.state_names, x0) if not np.isfinite(v)]
            raise SolverError(f"initial state is not finite in {', '.join(bad)}")
        if self.nx == 0:  # nothing to integrate: a system of sources and algebraic blocks
            return self._result(grid, np.zeros((0, grid.size)), p, {"wall_time_s": 0.0})
        integ = self._integrator(grid, rtol, atol, max_steps)
        start = time.perf_counter()
        try:
            xf = integ(x0=x0 / self.nominal, p=p)["xf"]
        except RuntimeError as exc:
            raise self._diagnose(str(exc), grid, x0, p, rtol, atol, max_steps) from None
        wall = time.perf_counter() - start
        X = np.asarray(xf, dtype=float) * self.nominal[:, None]
        if not np.all(np.isfinite(X)):
            k = int(np.argmax(~np.all(np.isfinite(X), axis=0)))
            bad = [n for n, v in zip(self.state_names, X[:, k]) if not np.isfinite(v)]
            raise SolverError(f"the solution became NaN/Inf at t = {grid[k]:.6g} s in {', '.join(bad)}")
        stats = {k: v for k, v in integ.stats().items() if not k.endswith("B") and isinstance(v, (int, float))}
        stats = {
            k: stats[k] for k in ("nsteps", "nfevals", "nlinsetups", "netfails", "nniters", "nncfails") if k in stats
        }
        stats["wall_time_s"] = wall
        return self._result(grid, X, p, stats)

    def _result(self, grid: np.ndarray, X: np.ndarray, p: np.ndarray, stats: dict[str, Any]) -> Result:
        nt = grid.size
        data: dict[str, np.ndarray] = {n: X[i] for i, n in enumerate(self.state_names)}

        def outputs() -> dict[str, np.ndarray]:
            if not self.output_names:
                return {}
            Y = np.asarray(self._outputs_map(nt)(grid[None, :], X, p[:, None]), dtype=float)
            return {n: Y[i] for i, n in enumerate(self.output_names)}

        params = dict(zip(self.parameter_names, p.tolist()))
        return Result(grid, data, dict(self.units), dict(self.descriptions), stats, params, self.name, outputs)

    def _outputs_map(self, n: int) -> ca.Function:
        if n not in self._maps:
            self._maps[n] = self.outputs.map(n)
        return self._maps[n]

    def _diagnose(
        self, message: str, grid: np.ndarray, x0: np.ndarray, p: np.ndarray, rtol: float, atol: float, max_steps: int
    ) -> SolverError:
        """Locate a failure: the last output time reached, and the state changing fastest there."""
        flag = next((k for k in _REASONS if k in message), None)
        reason = _REASONS[flag] if flag else message.strip().splitlines()[-1][:300]

        def reach(k: int) -> np.ndarray | None:
            """States at grid[:k + 1], or None if the integrator fails before grid[k]."""
            if k == 0:
                return x0[:, None]
            opts = {"abstol": atol, "reltol": rtol, "max_num_steps": max_steps, "disable_internal_warnings": True}
            sub = ca.integrator("diag", "cvodes", self._dae, float(grid[0]), [float(g) for g in grid[: k + 1]], opts)
            try:
                return np.asarray(sub(x0=x0 / self.nominal, p=p)["xf"], dtype=float) * self.nominal[:, None]
            except RuntimeError:
                return None

        lo, hi = 0, grid.size - 1  # grid[lo] is reached, grid[hi] is not
        states = x0[:, None]
        while hi - lo > 1:
            mid = (lo + hi) // 2
            got = reach(mid)
            if got is None or not np.all(np.isfinite(got)):
                hi = mid
            else:
                lo, states = mid, got
        last_t, last_x = float(grid[lo]), states[:, -1]
        rates = np.asarray(self.f(last_t, last_x, p), dtype=float).ravel() / self.nominal
        k = int(np.argmax(np.abs(np.where(np.isfinite(rates), rates, np.inf))))
        name = self.state_names[k]
        unit = si_unit(self.units.get(name, ""))
        return SolverError(
            f"integration of {self.name!r} failed at t = {last_t:.6g} to {float(grid[hi]):.6g} s: {reason}. "
            f"At t = {last_t:.6g} s the fastest-changing state was {name} = {last_x[k]:.6g} {unit} "
            f"(rate {rates[k] * self.nominal[k]:.3g} {unit}/s)."
        )

    # -- equilibrium -------------------------------------------------------
    def trim(
        self, p: np.ndarray, *, t: float = 0.0, x_guess: np.ndarray | None = None, tol: float = 1e-9
    ) -> dict[str, float]:
        """Equilibrium :math:`f(t, x, p) = 0` for the inputs at time ``t``.

        Solved by trust-region least squares on the scaled states with the exact
        Jacobian, from ``x_guess`` (default: the parameter-based initial state).
        Where the equilibrium is not unique (a free integrator, such as an
        open-loop cylinder), the solution nearest the guess is returned.

        Raises
        ------
        TrimError
            If the residual does not fall below ``tol`` (scaled rates, 1/s).
        """
        from scipy.optimize import least_squares  # SciPy's optimiser is imported where it is used: import stays fast

        p = np.asarray(p, dtype=float)
        x = np.asarray(self.x0(p), dtype=float).ravel() if x_guess is None else np.asarray(x_guess, dtype=float)
        z0 = x / self.nominal

        def res(z: np.ndarray) -> np.ndarray:
            return np.asarray(self._fz(t, z, p), dtype=float).ravel()

        def jac(z: np.ndarray) -> np.ndarray:
            return np.asarray(self._jz(t, z, p), dtype=float)

        sol = least_squares(res, z0, jac=jac, method="trf", xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=2000)
        r = res(sol.x)
        worst = int(np.argmax(np.abs(r)))
        if not np.all(np.isfinite(r)) or np.abs(r[worst]) > tol * max(
            1.0, np.abs(np.asarray(self._fz(t, z0, p))).max()
        ):
            raise TrimError(
                f"no equilibrium found for {self.name!r}: the largest remaining rate is in "
                f"{self.state_names[worst]} ({r[worst] * self.nominal[worst]:.3g} {si_unit(self.units[self.state_names[worst]])}/s)"
            )
        xs = sol.x * self.nominal
        return dict(zip(self.state_names, xs.tolist()))

    def linearize(self, x: np.ndarray | Mapping[str, float], p: np.ndarray, t: float = 0.0) -> np.ndarray:
        """Exact Jacobian :math:`A = \\partial f/\\partial x` at ``(t, x, p)`` (SI)."""
        if isinstance(x, Mapping):
            x = np.array([x[n] for n in self.state_names])
        return np.asarray(self.jac_x(t, x, p), dtype=float)

    # -- batch ---------------------------------------------------------------
    def batch(
        self,
        t_end: float,
        p_base: np.ndarray,
        sets: Mapping[str, Sequence[float]],
        *,
        n_points: int = 201,
        t_eval: Sequence[float] | None = None,
        rtol: float = 1e-6,
        atol: float = 1e-8,
        max_steps: int = 100_000,
        threads: int | None = None,
    ) -> BatchResult:
        """Run the model once per parameter set, the integrator mapped over all sets.

        ``sets`` maps parameter names to equally long sequences of SI values;
        other parameters keep ``p_base``. Runs are spread over ``threads``
        threads (default: all cores). Initial states follow the parameters.
        Outputs other than states are computed when first accessed.
        """
        grid = self._grid(t_end, t_eval, n_points)
        lengths = {len(v) for v in sets.values()}
        if len(lengths) != 1:
            raise ParameterError(f"batch: parameter sequences must be equally long; got lengths {sorted(lengths)}")
        n = lengths.pop()
        P = np.tile(np.asarray(p_base, dtype=float)[:, None], (1, n))
        for name, vals in sets.items():
            if name not in self.parameter_names:
                raise ParameterError(f"batch: unknown parameter {name!r}")
            P[self.parameter_names.index(name)] = np.asarray(vals, dtype=float)
        X0 = np.asarray(self.x0.map(n)(P), dtype=float) / self.nominal[:, None]
        nthreads = threads or os.cpu_count() or 1
        integ = self._integrator(grid, rtol, atol, max_steps)
        fmap = integ.map(n, "thread", nthreads)
        start = time.perf_counter()
        try:
            xf = fmap(x0=X0, p=P)["xf"]
        except RuntimeError as exc:
            raise SolverError(
                f"batch run of {self.name!r} failed in one of {n} runs: {str(exc).strip().splitlines()[-1][:300]}"
            ) from None
        wall = time.perf_counter() - start
        nt = grid.size
        X = np.asarray(xf, dtype=float).reshape(self.nx, n, nt) * self.nominal[:, None, None]
        data = {name: X[i] for i, name in enumerate(self.state_names)}
        fy = self._outputs_map(nt) if self.output_names else None

        def outputs() -> dict[str, np.ndarray]:
            if fy is None:
                return {}
            Y = np.stack(
                [np.asarray(fy(grid[None, :], X[:, k, :], P[:, k : k + 1]), dtype=float) for k in range(n)], axis=1
            )
            return {name: Y[i] for i, name in enumerate(self.output_names)}

        bad = ~np.all(np.isfinite(X), axis=(0, 2))
        if np.any(bad):
            raise SolverError(f"batch run of {self.name!r}: runs {np.flatnonzero(bad)[:10].tolist()} returned NaN/Inf")
        params = {name: P[i] for i, name in enumerate(self.parameter_names)}
        return BatchResult(
            grid,
            data,
            dict(self.units),
            params,
            {"wall_time_s": wall, "runs": n, "threads": nthreads},
            self.name,
            outputs,
        )

    # -- code generation ---------------------------------------------------
    def generate_c(self, filename: str | Path = "model.c") -> Path:
        """Write C code of ``f``, its Jacobian ``jac_x`` and the outputs ``y`` (CasADi code generation).

        The functions keep their CasADi names (``f``, ``jac_x``, ``y``) and
        calling convention; returns the path of the file written.
        """
        path = Path(filename)
        name = path.stem if path.stem.isidentifier() else "model"
        cg = ca.CodeGenerator(name + ".c", {"with_header": True})
        cg.add(self.f)
        cg.add(self.jac_x)
        cg.add(self.outputs)
        directory = path.parent.resolve()
        cg.generate(str(directory) + "/")
        written = directory / f"{name}.c"
        if written != path.resolve():
            written.replace(path)
            header = directory / f"{name}.h"
            if header.exists():
                header.replace(path.with_suffix(".h"))
            written = path
        return written
