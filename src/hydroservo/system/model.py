"""A built model: CasADi functions of one ODE, and the solvers that run it.

This is the only module that builds integrators (their settings and
messages: :mod:`hydroservo.system.integration`). States are integrated
in scaled form, :math:`z = x / x_{nom}`, where every component declares the
nominal magnitude of its states; so one scalar absolute tolerance means the
same thing for a pressure of 1e7 Pa and a spool position of 1e-5 m.
"""

from __future__ import annotations

import math
import os
import threading
import time
import warnings
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import casadi as ca
import numpy as np

from hydroservo.errors import (
    ImplausibleResultWarning,
    InterpretedWarning,
    ParameterError,
    SolverError,
    TrimError,
    did_you_mean,
)
from hydroservo.system.implicit import NEWTON_STEPS, TOLERANCE
from hydroservo.system.integration import (
    AUTO_MAX_STATES,
    AUTO_METHOD,
    DEFAULT_METHOD,
    Interrupted,
    SolverSettings,
    batch_columns,
    captured,
    check_method,
    failure_point,
    interruptible,
    output_grid,
    translate,
)
from hydroservo.system.plausibility import Implausible, check
from hydroservo.system.result import BatchResult, Result
from hydroservo.units import si_unit

if TYPE_CHECKING:
    from hydroservo.system.assembly import Assembly

__all__ = ["Model"]

_INTERPRETED_SAID = threading.Event()
#: The largest entry of the Jacobian on the scaled states at the start of a run [1/s]: a time scale of 1e-20 s,
#: ten orders of magnitude beyond the largest entry among 300 random sets of the flight simulator and the
#: servo-solenoid cylinder varying every parameter (4e10 1/s; fuzz_models.py --all-prob 1 --seed 1), and below
#: where CVODES starts to fail (position-servo's load.B: it runs at an entry of 1e28 1/s, fails at 1e33).
FASTEST_RATE = 1e20
#: A state beyond this many times its nominal magnitude where a run failed: the solution diverged.
RUNAWAY = 1e6


def _progress_of(
    progress: Callable[[int, int], None] | bool | None, total: int, name: str
) -> tuple[Callable[[int, int], None] | None, Any]:
    """A batch's ``progress``: the callable to report to, and the bar to close (``progress=True``: tqdm's, in
    a terminal or a notebook)."""
    if progress is not True:
        return (progress or None), None
    from tqdm.auto import tqdm

    bar = tqdm(total=total, desc=f"{name}: runs", unit="run")

    def report(done: int, _total: int) -> None:
        bar.n = done
        bar.refresh()

    return report, bar


def _interrupted(stop: Any, message: str, printed: str) -> bool:
    """Whether CVODES stopped because of Ctrl-C: CasADi runs Python's SIGINT handler in its callbacks, and the
    callback that met the KeyboardInterrupt fails the integration (CV_RHSFUNC_FAIL, CV_LSETUP_FAIL, ...);
    ``stop`` is the flag :func:`~hydroservo.system.integration.interruptible` armed for the run (or None)."""
    return bool(stop is not None and stop.value) or "KeyboardInterrupt" in message or "KeyboardInterrupt" in printed


def _interpreted_once(
    why: str, remedy: str = "Install a C compiler (cc, gcc or clang) for the compiled solvers, or pass"
) -> None:
    """Say once a process that ``method="auto"`` runs CVODES in CasADi's interpreter, why, and the remedy."""
    if not _INTERPRETED_SAID.is_set():
        _INTERPRETED_SAID.set()
        warnings.warn(
            f"simulating with CVODES in CasADi's interpreter, 2 to 5 times slower than compiled ({why}). "
            f"{remedy} method='cvodes' (on the command line --method cvodes) to choose it",
            InterpretedWarning,
            stacklevel=5,
        )

#: The largest expression a batch's outputs or plausibility checks are unrolled into over the output times
#: [instructions]: beyond it (many times, many outputs), the mapped function is kept as it is.
UNROLLED_SIZE = 3_000_000

#: A single run's output or plausibility function is unrolled over its output times (one expression graph,
#: 2-5x faster per call than the mapped function, but 5-20 ms to build) at the call that uses it this many
#: times: a loop of warm calls gains, a one-off run does not pay for it.
UNROLL_AFTER = 3

#: ... and only if the unrolled graph holds at most this many instructions (a larger one takes longer to build
#: than the calls it would save): the flight-simulator's y over 1001 times holds 4 000, its plausibility
#: checks 24 000, all its outputs 153 000.
UNROLLED_WARM = 60_000


def _buffered(
    fn: ca.Function, args: Mapping[int, np.ndarray], *, raises: bool = False, stats: dict[str, Any] | None = None
) -> tuple[np.ndarray, int]:
    """``fn``'s first output (a dense matrix) for the inputs ``args`` (input index -> a dense matrix of that
    input's shape; the other inputs empty), and its return code (0: success). With ``raises``, a failure
    raises CasADi's ``RuntimeError`` (with the integrator's message, where it gives one) instead; ``stats``,
    if given, receives the evaluation's statistics (an integrator's steps).

    Evaluated on NumPy's memory through CasADi's function buffer, in CasADi's column-major order: no
    conversion to and from CasADi matrices, which costs more than the evaluation for a batch's states
    (about 60 ns a number each way).
    """
    rows, columns = fn.size_out(0)
    if not fn.sparsity_out(0).is_dense():  # the buffer holds nonzeros only: every function here is made dense
        raise RuntimeError(f"{fn.name()}: its output is not dense; build it with ca.densify")
    buffer, evaluate = fn.buffer()
    kept = []  # the inputs' memory, alive until the evaluation is done
    for i, a in args.items():
        flat = np.ascontiguousarray(np.asarray(a, dtype=float).ravel(order="F"))
        if flat.size:
            kept.append(flat)
            buffer.set_arg(i, flat.data)  # type: ignore[call-arg]
    out = np.zeros(rows * columns)
    if out.size:
        buffer.set_res(0, out.data)  # type: ignore[call-arg]
    try:
        evaluate()
    except RuntimeError:  # a function that raises rather than returns its failure (a map of one, serial)
        if raises:
            raise
        return out.reshape((rows, columns), order="F"), 1
    code = int(buffer.ret())
    if stats is not None:
        stats.update(buffer.stats())
    if code and raises:
        raise RuntimeError(f"{fn.name()} returned {code}")
    return out.reshape((rows, columns), order="F"), code

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

    def __init__(self, assembly: Assembly) -> None:
        """Compile ``assembly`` (:func:`hydroservo.system.assembly.assemble`)."""
        a = assembly
        name, t, x, p, f, y, x0 = a.name, a.t, a.x, a.p, a.f, a.y, a.x0
        state_names, parameter_names, output_names = a.state_names, a.parameter_names, a.output_names
        units, descriptions, nominal, parameter_units = a.units, a.descriptions, a.nominal, a.parameter_units
        limits, convergence = a.limits, a.convergence
        #: what the model was compiled from (its graph, for code generation and linearisation)
        self.assembly = assembly
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
        # The outputs on the scaled states, as the integrator returns them: a result reads its outputs
        # from the integrator's own matrix, with no conversion through NumPy.
        self._yz = (t, z, p, ca.substitute(y, x, z * nom))
        self._output_index = {name: i for i, name in enumerate(output_names)}
        self._state_index = {name: i for i, name in enumerate(state_names)}
        #: Signals under a physical limit, checked after every run (:mod:`hydroservo.system.plausibility`).
        self.watched = [w for w, *_ in limits]
        # A watched state is read from the solution; other watched signals are evaluated on the scaled
        # states, mapped over the output times; the bounds are parameters, evaluated once per run.
        self._watch_rows: list[tuple[str, int]] = []
        computed: list[Any] = []
        for w, value, _, _ in limits:
            if w.signal in state_names:
                self._watch_rows.append(("state", state_names.index(w.signal)))
            else:
                self._watch_rows.append(("computed", len(computed)))
                computed.append(ca.substitute(ca.SX(value), x, z * nom))
        self._limit_values = ca.Function("limit_values", [t, z, p], [ca.vertcat(*computed) if computed else ca.SX(0, 1)])
        lowers = [ca.SX(lower) for _, _, lower, _ in limits]
        uppers = [ca.SX(upper) for _, _, _, upper in limits]
        bounds = [ca.vertcat(*col) if col else ca.SX(0, 1) for col in (lowers, uppers)]
        #: ``limit_bounds(p) -> (lower, upper)``: the bounds of :attr:`watched`, evaluated at the parameters ``p``
        self.limit_bounds = ca.Function("limit_bounds", [p], bounds)
        #: Algebraic unknowns solved inside the model (:mod:`hydroservo.system.implicit`), recorded as outputs.
        self.algebraic_names: list[str] = list(convergence[0]) if convergence else []
        correction = ca.substitute(convergence[1], x, z * nom) if convergence else ca.SX(0, 1)
        self._convergence = ca.Function("convergence", [t, z, p], [correction])
        self._integrators: dict[Any, ca.Function] = {}
        self._maps: dict[Any, ca.Function] = {}
        self._sizes: dict[tuple[str, ...], int] = {}
        self._limit_maps: dict[Any, ca.Function] = {}
        self._uses: dict[Any, int] = {}
        self._batch_maps: dict[tuple[int, int, int], ca.Function] = {}

    # -- helpers -----------------------------------------------------------
    def _integrator(self, grid: np.ndarray, settings: SolverSettings) -> ca.Function:
        steps = settings.steps_per_interval(grid.size - 1)
        key = (grid.tobytes(), settings.rtol, settings.atol, steps)
        if key not in self._integrators:
            self._make_room()
            # CVODES' own warnings stay on: they are captured, and on a failure they give its time and step
            opts = {"abstol": settings.atol, "reltol": settings.rtol, "max_num_steps": steps}
            self._integrators[key] = ca.integrator(
                "sim", "cvodes", self._dae, float(grid[0]), [float(g) for g in grid], opts
            )
        return self._integrators[key]

    def _make_room(self) -> None:
        """Before an integrator is added: past 16 kept (one per output grid and tolerance), start afresh."""
        if len(self._integrators) > 16:
            self._integrators.clear()
            self._batch_maps.clear()

    def _interval_integrator(self, settings: SolverSettings, steps: int) -> ca.Function:
        """One output interval at a time, in normalised time: parameters ``[p, t0, h]``, tau from 0 to 1.
        Used to locate a failure; CVODES' own messages are kept (they give the time and step at failure)."""
        key = ("interval", settings.rtol, settings.atol, steps)
        if key not in self._integrators:
            z, t, p, fz = self._dae["x"], self._dae["t"], self._dae["p"], self._dae["ode"]
            tau, t0, h = ca.SX.sym("tau"), ca.SX.sym("t0"), ca.SX.sym("h")
            dae = {"x": z, "t": tau, "p": ca.vertcat(p, t0, h), "ode": h * ca.substitute(fz, t, t0 + tau * h)}
            opts = {"abstol": settings.atol, "reltol": settings.rtol, "max_num_steps": steps}
            self._integrators[key] = ca.integrator("interval", "cvodes", dae, 0.0, 1.0, opts)
        return self._integrators[key]

    def _check_parameters(self, p: Any) -> np.ndarray:
        vec = np.asarray(p, dtype=float).ravel()
        if vec.size != self.np:
            raise ParameterError(f"parameter vector of {self.name!r}: {vec.size} values; expected {self.np}")
        if not np.all(np.isfinite(vec)):
            k = int(np.argmax(~np.isfinite(vec)))
            raise ParameterError(f"{self.parameter_names[k]} = {vec[k]!r}: expected a finite value")
        return vec

    def unconverged(self, grid: np.ndarray, Z: np.ndarray, p: np.ndarray) -> str | None:
        """Why the algebraic unknowns were not solved at some output time (``Z``: scaled states), or None."""
        if not self.algebraic_names:
            return None
        C = np.asarray(self._convergence.map(grid.size)(grid[None, :], Z, p), dtype=float).reshape(
            len(self.algebraic_names), grid.size
        )
        bad = ~(C <= TOLERANCE)  # NaN counts as not converged
        if not bad.any():
            return None
        j, k = (int(v) for v in np.argwhere(bad)[0])
        name = self.algebraic_names[j]
        return (
            f"the algebraic unknown {name} ({self.descriptions.get(name, '')}) was not solved at t = {grid[k]:.6g} s: "
            f"Newton's last correction was {C[j, k]:.3g} of its nominal magnitude after {NEWTON_STEPS} steps "
            f"(accepted: {TOLERANCE:g}); the first guess is too far from the solution there, or the equation has "
            "no solution"
        )

    def _check_initial(self, x0: np.ndarray) -> None:
        if not np.all(np.isfinite(x0)):
            bad = [f"{n} = {v!r}" for n, v in zip(self.state_names, x0) if not np.isfinite(v)]
            raise ParameterError(f"initial state of {self.name!r} is not finite: {', '.join(bad)}")

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
                raise ParameterError(f"initial: {name!r} is not a state{did_you_mean(name, self.state_names)}; states: {', '.join(self.state_names)}")
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
        rtol: float | None = None,
        atol: float | None = None,
        max_steps: int | None = None,
        initial: str | Mapping[str, float] = "parameters",
        accuracy: float | None = None,
        method: str = DEFAULT_METHOD,
        events: bool = True,
    ) -> Result:
        """Integrate with a compiled variable-step method, or with CVODES (BDF, Newton with the exact Jacobian).

        Parameters
        ----------
        t_end : float
            Duration [s] (ignored when ``t_eval`` is given).
        p : array
            Parameter vector (SI) in the order of :attr:`parameter_names`.
        t_eval : sequence of float, optional
            Output times [s], strictly increasing, at most 100 001; the first is the initial time.
        n_points : int
            Number of equally spaced output times when ``t_eval`` is not given (2 to 100 001).
        rtol, atol : float
            Relative tolerance (1e-14 to 0.1), and absolute tolerance (above 0, at most 1)
            on states scaled by their nominal magnitude; ``atol`` is ``rtol / 100`` unless given.
        accuracy : float
            Instead of the tolerances: the deviation wanted, relative to each signal's range;
            ``rtol = accuracy / 100`` (:func:`hydroservo.system.integration.tolerances`). Neither
            given: 1e-4, i.e. rtol 1e-6 and atol 1e-8.
        max_steps : int
            Step budget of the run (CVODES: shared out over the output intervals, at least 500
            each): a hopeless parameter set fails in about this many steps. Default: 100 000 at
            rtol 1e-6 and looser, more at tighter tolerances
            (:func:`~hydroservo.system.integration.default_max_steps`), and ten times that for the
            compiled methods, whose steps are cheap (a compiled run that stops advancing fails within
            10 000 steps, whatever the budget).
        initial : "parameters", "trim" or mapping
            Initial state, see :meth:`initial_state`.
        method : str
            ``"auto"`` (default): ``"rodas3"`` for a model of at most 20 states
            (:data:`~hydroservo.system.integration.AUTO_MAX_STATES`) where it compiles (a C compiler is found),
            else ``"cvodes"`` (no compiler: said once per process). The compiled methods
            (:data:`~hydroservo.system.native.ADAPTIVE_METHODS`, :mod:`hydroservo.system.native`; C built once per
            model structure and kept in the user's cache folder): ``"rodas3"`` (Sandu et al.'s Rosenbrock 3(2) on
            the exact Jacobian, L-stable, for stiff circuits: every built-in model), ``"ros23"`` (Rosenbrock 2(3), cheaper steps at loose accuracy) or ``"dopri5"``
            (explicit Dormand-Prince 5(4), for circuits that are not stiff). ``"cvodes"``: SUNDIALS' BDF through
            CasADi's interpreter, no compiler needed. ``Result.stats["method"]`` says which ran; docs/engine.md
            compares them.
        events : bool
            Compiled methods: end a step at each kink or jump the components declare (end stops, a chamber at
            its pressure floor, a valve cracking, a source's step) rather than step across it. CVODES has none.

        Raises
        ------
        ParameterError
            If a setting, a parameter or the initial state is not acceptable.
        SolverError
            If the integrator fails; the message gives the time, the state, the
            reason and the fastest mode of the model there.
        """
        grid = output_grid(t_end, t_eval, n_points)
        method = self._resolve(check_method(method))
        settings = SolverSettings.of(rtol, atol, accuracy, max_steps, method=method)
        p = self._check_parameters(p)
        x0 = self.initial_state(p, initial, t0=float(grid[0]))
        self._check_initial(x0)
        if self.nx == 0:  # nothing to integrate: a system of sources and algebraic blocks
            return self._result(grid, np.zeros((0, grid.size)), p, {"wall_time_s": 0.0})
        why = self.unconverged(grid[:1], (x0 / self.nominal)[:, None], p)
        if why is not None:
            raise SolverError(f"integration of {self.name!r} cannot start: {why}")
        self._check_time_scale(float(grid[0]), x0, p)
        if method != "cvodes":
            return self._compiled_run(method, grid, x0, p, settings, events)
        integ = self._integrator(grid, settings)
        start = time.perf_counter()
        found: dict[str, Any] = {}  # the integrator's statistics
        try:
            with interruptible() as stop, captured() as printed:
                args = {integ.index_in("x0"): x0 / self.nominal, integ.index_in("p"): p}
                xf, _ = _buffered(integ, args, raises=True, stats=found)
        except RuntimeError as exc:
            if _interrupted(stop, str(exc), printed.getvalue()):  # CasADi ran Python's SIGINT handler in a callback
                t_stop, _ = failure_point(printed.getvalue())
                raise Interrupted(f"simulation of {self.name!r} (cvodes)", t_stop, float(grid[-1])) from None
            raise self._diagnose(str(exc), printed.getvalue(), grid, x0, p, settings) from None
        wall = time.perf_counter() - start
        if not np.isfinite(xf).all():
            X = xf * self.nominal[:, None]
            k = int(np.argmax(~np.all(np.isfinite(X), axis=0)))
            bad = [n for n, v in zip(self.state_names, X[:, k]) if not np.isfinite(v)]
            raise SolverError(
                f"integration of {self.name!r}: the solution became NaN/Inf between t = {grid[k - 1]:.6g} s "
                f"and {grid[k]:.6g} s in {', '.join(bad)}. {self._hint(float(grid[k - 1]), X[:, k - 1], p)}"
            )
        why = self.unconverged(grid, xf, p)
        if why is not None:
            raise SolverError(f"integration of {self.name!r}: {why}")
        kept = ("nsteps", "nfevals", "nlinsetups", "netfails", "nniters", "nncfails")
        stats: dict[str, Any] = {k: found[k] for k in kept if isinstance(found.get(k), (int, float))}
        stats.update({"method": "cvodes", "rtol": settings.rtol, "atol": settings.atol, "wall_time_s": wall})
        return self._result(grid, None, p, stats, xf)

    def _check_time_scale(self, t0: float, x0: np.ndarray, p: np.ndarray) -> None:
        """Refuse a start whose Jacobian (on the scaled states) has an entry beyond :data:`FASTEST_RATE`: a time
        scale no circuit has, which only a parameter out of all proportion gives (``B = 1e300 N*s/m``). Neither
        method integrates it reliably in double precision (the compiled ones step over it, CVODES overflows), so
        both refuse it alike, naming the entry and the parameters it grows with."""
        A = np.asarray(self._jz(t0, x0 / self.nominal, p), dtype=float)
        with np.errstate(invalid="ignore"):
            bad = np.abs(A) > FASTEST_RATE  # Inf counts; NaN (a law without a derivative there) is the solver's to say
        if not bad.any():
            return
        i, j = (int(v) for v in np.argwhere(bad)[0])
        t, z, ps = self._dae["t"], self._dae["x"], self._dae["p"]
        entry = ca.jacobian(self._dae["ode"][i], z)[j]
        dA = ca.jacobian(entry, ps)
        depends = np.asarray(ca.DM(dA.sparsity(), 1), dtype=float).ravel() > 0
        grad = np.asarray(ca.Function("dA_dp", [t, z, ps], [dA])(t0, x0 / self.nominal, p), dtype=float).ravel()
        with np.errstate(all="ignore"):
            share = np.abs(grad * p / A[i, j])  # the entry's log-sensitivity to each parameter
            extreme = np.where(p != 0, np.abs(np.log10(np.abs(p))), 0.0)  # among equal shares, furthest from 1 first
        if not np.isfinite(A[i, j]):  # no sensitivity to speak of: the parameters it depends on, extreme first
            share = depends.astype(float)
        share = np.where(depends, np.nan_to_num(share, nan=np.inf), 0.0)
        order = [k for k in np.lexsort((-extreme, -share)) if share[k] > 0.1]
        named = [
            f"{self.parameter_names[k]} = {p[k]:.4g} {si_unit(self.parameter_units.get(self.parameter_names[k], ''))}".rstrip()
            for k in order[:4]
        ]
        xi, xj = self.state_names[i], self.state_names[j]
        ui, uj = (si_unit(self.units.get(n, "")) for n in (xi, xj))
        unit = "1/s" if ui == uj else f"{ui or '1'}/s per {uj or 'unit'}"
        value = A[i, j] * self.nominal[i] / self.nominal[j]
        scale = f"a time scale of {1 / abs(A[i, j]):.3g} s" if np.isfinite(A[i, j]) and A[i, j] != 0 else "no finite time scale"
        head = f"{named[0]} is out of all proportion" if named else f"{self.name!r} cannot be integrated"
        raise ParameterError(
            f"{head}: at the start the rate of {xi} changes with {xj} by {value:.3g} {unit} ({scale}; the limit, on "
            f"the states scaled by their nominal magnitudes, is {FASTEST_RATE:.0e} 1/s: no circuit has a mode that "
            f"fast, and neither solver integrates one reliably in double precision); that rate grows with "
            f"{', '.join(named) if named else 'no parameter'}: check the value and its unit"
        )

    def _resolve(self, method: str) -> str:
        """The method ``method`` names: ``auto`` is :data:`~hydroservo.system.integration.AUTO_METHOD` if this
        model has at most :data:`~hydroservo.system.integration.AUTO_MAX_STATES` states and compiles, else
        ``cvodes`` (with a :class:`~hydroservo.errors.InterpretedWarning` once a process if it does not compile)."""
        if method != "auto":
            return method
        if self.nx > AUTO_MAX_STATES:
            return "cvodes"
        from hydroservo.system.native import CacheFolderError, native

        try:
            native(self)
        except CacheFolderError as exc:
            _interpreted_once(str(exc), "Pass")
            return "cvodes"
        except ParameterError as exc:
            _interpreted_once(str(exc))
            return "cvodes"
        return AUTO_METHOD

    def _compiled_solvers(self, method: str) -> Any:
        """The compiled solvers of this model (:func:`hydroservo.system.native.native`), or why not."""
        from hydroservo.system.native import CacheFolderError, native

        try:
            return native(self)
        except CacheFolderError:  # it says which folder, and what to do
            raise
        except ParameterError as exc:
            raise ParameterError(
                f"method = {method!r} runs the model compiled to C, which needs a C compiler: {exc}. "
                "method='cvodes' needs none"
            ) from None

    def _compiled_run(
        self, method: str, grid: np.ndarray, x0: np.ndarray, p: np.ndarray, settings: SolverSettings, events: bool
    ) -> Result:
        """One run of a compiled variable-step method (:mod:`hydroservo.system.native`)."""
        solver = self._compiled_solvers(method)
        start = time.perf_counter()
        try:
            X, stats, failure, t_reached, x_reached = solver.integrate(
                p, x0, grid, method=method, rtol=settings.rtol, atol=settings.atol, max_steps=settings.max_steps,
                events=events,
            )
        except Interrupted as exc:
            raise Interrupted(f"simulation of {self.name!r} ({method}, compiled)", exc.t, exc.t_end) from None
        wall = time.perf_counter() - start
        if failure is not None:
            raise SolverError(
                f"integration of {self.name!r} ({method}, compiled) failed: {failure}. "
                f"{self._hint(t_reached, x_reached, p)}"
            )
        why = self.unconverged(grid, X / self.nominal[:, None], p)
        if why is not None:
            raise SolverError(f"integration of {self.name!r}: {why}")
        stats.update({"method": method, "rtol": settings.rtol, "atol": settings.atol, "wall_time_s": wall})
        return self._result(grid, X, p, stats)

    def _diagnose(
        self,
        message: str,
        printed: str,
        grid: np.ndarray,
        x0: np.ndarray,
        p: np.ndarray,
        settings: SolverSettings,
    ) -> SolverError:
        """Where and why a run failed, at the cost of one more integration.

        The run is repeated one output interval at a time, so the state at the
        start of the failing interval is known, and CVODES says at what time and
        step size it gave up (in the re-run, or in ``printed``, what the original
        run printed, when the re-run passes); the model linearised there names
        the fastest mode.
        """
        reason = translate(message)
        t_fail, h_fail = failure_point(printed)
        steps = settings.steps_per_interval(grid.size - 1)
        step = self._interval_integrator(settings, steps)
        z = x0 / self.nominal
        reached = [z]  # scaled states at grid[0], grid[1], ... as far as the re-run gets
        k_fail: int | None = None
        for k in range(grid.size - 1):
            h = float(grid[k + 1] - grid[k])
            try:
                with captured() as out:
                    nxt = np.asarray(step(x0=z, p=np.concatenate([p, [grid[k], h]]))["xf"], dtype=float).ravel()
            except RuntimeError:
                k_fail = k
                tau, h_tau = failure_point(out.getvalue())  # in the re-run's normalised time
                if tau is not None:  # the re-run's failure, consistent with the state it reached
                    t_fail, h_fail = grid[k] + tau * h, (None if h_tau is None else abs(h_tau) * h)
                elif t_fail is not None and not grid[k] <= t_fail <= grid[k + 1]:
                    t_fail = h_fail = None  # the original run gave up elsewhere: not this interval's figures
                break
            if not np.all(np.isfinite(nxt)):
                k_fail = k
                break
            z = nxt
            reached.append(z)
        if k_fail is None:  # the re-run passed: the original failure time places the interval
            k_fail = grid.size - 2 if t_fail is None else int(np.clip(np.searchsorted(grid, t_fail) - 1, 0, grid.size - 2))
            note = (
                "; repeated one output interval at a time it did not fail, so the failure depends on the step "
                "history: tighten rtol or refine the output grid"
            )
        else:
            note = ""
        t0, t1 = float(grid[k_fail]), float(grid[k_fail + 1])
        where = f"integration of {self.name!r} failed between t = {t0:.6g} s and {t1:.6g} s: {reason}"
        if t_fail is not None:
            where += f"; CVODES stopped at t = {t_fail:.6g} s"
            if h_fail is not None:
                where += f" with a step of {abs(h_fail):.3g} s"
            elif "TOO_MUCH_WORK" in message:
                where += (
                    f" after {steps} steps in this interval (mean step {max(t_fail - t0, 0.0) / steps:.3g} s; "
                    f"max_steps = {settings.max_steps} shared over {grid.size - 1} output intervals: a model that "
                    "is only slow here runs with a larger max_steps (simulate --max-steps) or fewer output points; a "
                    "stiff circuit whose steps CVODES keeps short, with the compiled Rosenbrock method "
                    "(--method rodas3))"
                )
        z = reached[min(k_fail, len(reached) - 1)]
        why = self.unconverged(np.array([t0]), z[:, None], p)
        if why is not None:  # the cause, more likely than anything the linearisation says
            where += f"; {why}"
        return SolverError(f"{where}{note}. {self._hint(t0, z * self.nominal, p)}")

    def _hint(self, t: float, x: np.ndarray, p: np.ndarray) -> str:
        """The state changing fastest at (t, x), and the fastest mode of the model linearised there."""
        rates = np.asarray(self.f(t, x, p), dtype=float).ravel() / self.nominal
        k = int(np.argmax(np.abs(np.where(np.isfinite(rates), rates, np.inf))))
        unit = si_unit(self.units.get(self.state_names[k], ""))
        text = ""
        size = np.abs(np.where(np.isfinite(x), x, np.inf)) / self.nominal
        if size.max() > RUNAWAY:  # the cause: nothing bounds the solution, no step control helps
            r = int(np.argmax(size))
            text = (
                f"The solution diverges: {self.state_names[r]} reached {x[r]:.3g} "
                f"{si_unit(self.units.get(self.state_names[r], ''))}, {size[r]:.1e} times its nominal magnitude "
                "(an unstable loop that nothing in the model bounds, for these parameters). "
            )
        text += (
            f"At t = {t:.6g} s the state changing fastest was {self.state_names[k]} = {x[k]:.6g} {unit} "
            f"(rate {rates[k] * self.nominal[k]:.3g} {unit}/s)"
        )
        A = np.asarray(self._jz(t, x / self.nominal, p), dtype=float)
        if not np.all(np.isfinite(A)):
            i, j = (int(v) for v in np.argwhere(~np.isfinite(A))[0])
            return text + (
                f"; the Jacobian there is not finite: the rate of {self.state_names[i]} has a derivative of {A[i, j]} "
                f"in {self.state_names[j]} (a law without a derivative at this point: a square root or an absolute "
                "value at zero with no regularisation, a division by zero)."
            )
        lam, vec = np.linalg.eig(A)
        i = int(np.argmax(np.abs(lam)))
        weight = np.abs(vec[:, i])
        names = [self.state_names[j] for j in np.argsort(-weight) if weight[j] > 0.3 * weight.max()][:3]
        mode = lam[i]
        shown = f"{mode.real:.3g}" if abs(mode.imag) <= 1e-9 * abs(mode) else f"{mode.real:.3g} ± {abs(mode.imag):.3g}j"
        text += (
            f"; the fastest mode of the model linearised there has an eigenvalue of {shown} 1/s "
            f"(time scale {1 / abs(mode):.3g} s), mostly in {', '.join(names)}"
        )
        grow = int(np.argmax(lam.real))
        if lam[grow].real > 1e-6 * abs(lam[i]):
            w = np.abs(vec[:, grow])
            growing = [self.state_names[j] for j in np.argsort(-w) if w[j] > 0.3 * w.max()][:3]
            text += f"; the model is unstable there (a mode grows at {lam[grow].real:.3g} 1/s, mostly in {', '.join(growing)})"
        if all(si_unit(self.units.get(n, "")) == "Pa" for n in names):
            text += "; fast pressure modes come from small volumes, a large bulk modulus or large areas"
        return text + "."

    def _result(
        self, grid: np.ndarray, X: np.ndarray | None, p: np.ndarray, stats: dict[str, Any], Z: Any = None
    ) -> Result:
        """A run's result: ``X`` the states (SI) at the times ``grid``, or ``Z`` the integrator's matrix of the
        scaled states; its signals are read from ``Z`` when first asked for, only those asked for."""
        nt = grid.size
        z = Z if Z is not None else np.asarray(X) / self.nominal[:, None]

        def signals(names: Sequence[str]) -> dict[str, np.ndarray]:
            states = [n for n in names if n in self._state_index]
            outputs = [n for n in names if n not in self._state_index]
            out: dict[str, np.ndarray] = {}
            if states:
                rows = [self._state_index[n] for n in states]
                S = np.asarray(z[rows, :], dtype=float) * self.nominal[rows, None]
                out.update((n, S[i]) for i, n in enumerate(states))
            if outputs:
                Y, _ = _buffered(self._output_function(outputs, nt), {0: grid[None, :], 1: z, 2: p}, raises=True)
                out.update((n, Y[i]) for i, n in enumerate(outputs))
            return out

        params = dict(zip(self.parameter_names, p.tolist()))
        result = Result(
            grid, {}, dict(self.units), dict(self.descriptions), stats, params, self.name, signals,
            [*self.state_names, *self.output_names],
        )  # fmt: skip
        result.warnings = self.plausibility(grid, X, p, Z)
        if result.warnings:
            more = f" (and {len(result.warnings) - 1} more)" if len(result.warnings) > 1 else ""
            warnings.warn(
                f"physically implausible result of {self.name!r}: {result.warnings[0]}{more}; see Result.warnings",
                ImplausibleResultWarning,
                stacklevel=4,
            )
        return result

    def plausibility(self, grid: np.ndarray, X: np.ndarray | None, p: np.ndarray, Z: Any = None) -> list[Implausible]:
        """The physical bounds one run crossed (:mod:`hydroservo.system.plausibility`).

        ``X`` holds the states (SI) at the output times ``grid``, or ``Z`` the same scaled by the nominal
        magnitudes as the integrator returned them. The watched signals' extremes are computed first, in
        one call; only a run that crosses a bound has its signals read in full, to say where.
        """
        if not self.watched:
            return []
        z = Z if Z is not None else np.asarray(X) / self.nominal[:, None]
        lo, hi = (np.asarray(b, dtype=float).ravel() for b in self.limit_bounds(p))
        extremes, _ = _buffered(self._limit_extremes(grid.size), {0: grid[None, :], 1: z, 2: p}, raises=True)
        if not check(grid[[0, -1]], self.watched, extremes, lo, hi):  # check reads only the extremes' verdicts
            return []
        if X is None:
            X = np.asarray(z, dtype=float) * self.nominal[:, None]
        computed = np.zeros((0, grid.size))
        if any(kind == "computed" for kind, _ in self._watch_rows):
            computed = np.asarray(self._limit_function(grid.size)(grid[None, :], z, p), dtype=float)
        return self._check_limits(grid, X, computed, p)

    def _limit_extremes(self, nt: int) -> ca.Function:
        """``(t, z, p) -> [min, max]`` over ``nt`` times of every watched signal, a row each; kept once built."""
        key = ("extremes", nt)
        if key not in self._limit_maps:
            T, Z, P = ca.MX.sym("t", 1, nt), ca.MX.sym("z", self.nx, nt), ca.MX.sym("p", self.np)
            C = self._limit_function(nt)(T, Z, P)
            rows = [Z[i, :] * float(self.nominal[i]) if kind == "state" else C[i, :] for kind, i in self._watch_rows]
            lows = ca.vertcat(*[ca.mmin(r) for r in rows])
            highs = ca.vertcat(*[ca.mmax(r) for r in rows])
            self._limit_maps[key] = ca.Function("limit_extremes", [T, Z, P], [ca.densify(ca.horzcat(lows, highs))])
        return self._warmed(self._limit_maps, key, self._limit_values.n_instructions() * nt)

    def _check_limits(self, grid: np.ndarray, X: np.ndarray, computed: np.ndarray, p: np.ndarray) -> list[Implausible]:
        V = np.array([X[i] if kind == "state" else computed[i] for kind, i in self._watch_rows])
        lo, hi = (np.asarray(b, dtype=float).ravel() for b in self.limit_bounds(p))
        return check(grid, self.watched, V, lo, hi)

    def _limit_function(self, nt: int) -> ca.Function:
        """The watched signals that are not states, at ``nt`` times; kept once built."""
        key = ("values", nt)
        if key not in self._limit_maps:
            self._limit_maps[key] = self._limit_values.map("limit_values", "serial", nt, [2], [])
        return self._limit_maps[key]

    def _output_function(self, names: Sequence[str], nt: int) -> ca.Function:
        """The outputs ``names`` at ``nt`` times of a run, on the scaled states: ``(t, z, p) -> y``; kept once
        built for that selection."""
        key = (tuple(names), nt)
        if key not in self._maps:
            if len(self._maps) > 64:
                self._maps.clear()
                self._uses.clear()
            t, z, p, yz = self._yz
            rows = [self._output_index[n] for n in names]
            one = ca.Function("y", [t, z, p], [ca.densify(yz[rows]) if rows else ca.SX(0, 1)])
            self._maps[key] = one.map("outputs", "serial", nt, [2], [])  # p shared over the times
        return self._warmed(self._maps, key, self._output_size(names) * nt)

    def _warmed(self, store: dict[Any, ca.Function], key: Any, size: int) -> ca.Function:
        """``store[key]``, a function ``(t, z, p)`` of one run's output times; at its :data:`UNROLL_AFTER`-th use,
        replaced by the same unrolled into one expression graph if that holds at most :data:`UNROLLED_WARM`
        instructions (``size``)."""
        uses = self._uses[key] = self._uses.get(key, 0) + 1
        if uses == UNROLL_AFTER and size <= UNROLLED_WARM:
            mapped = store[key]
            args = [ca.SX.sym(mapped.name_in(i), mapped.sparsity_in(i)) for i in range(3)]
            store[key] = ca.Function(mapped.name(), args, [mapped(*args)])
        return store[key]

    def _output_size(self, names: Sequence[str]) -> int:
        """Instructions to evaluate the outputs ``names`` at one time."""
        key = tuple(names)
        if key not in self._sizes:
            t, z, p, yz = self._yz
            rows = [self._output_index[n] for n in names]
            self._sizes[key] = ca.Function("y", [t, z, p], [yz[rows] if rows else ca.SX(0, 1)]).n_instructions()
        return self._sizes[key]

    def _over_runs(
        self, what: Any, over_time: ca.Function, per_time: int, grid: np.ndarray, runs: int, threads: int
    ) -> ca.Function:
        """``over_time`` (a function ``(t, z, p)`` of one run) for ``runs`` runs side by side on the times
        ``grid``: ``(z, p)``, their scaled states one run after the other and a parameter column each, spread
        over ``threads``. Unrolled into one expression graph with the times as constants, which evaluates
        5-10x faster per time than the mapped function, unless ``per_time`` (instructions at one time) times
        the number of times exceeds :data:`UNROLLED_SIZE`; kept once built (a batch's chunks share it)."""
        threads = max(1, min(threads, runs))
        key = ("runs", what, grid.size, hash(grid.tobytes()), runs, threads)
        if key not in self._maps:
            if len(self._maps) > 64:
                self._maps.clear()
            times = ca.DM(grid[None, :])
            if per_time * grid.size <= UNROLLED_SIZE:
                z, p = ca.SX.sym("z", self.nx, grid.size), ca.SX.sym("p", self.np)
                one = ca.Function("run", [z, p], [over_time.expand()(times, z, p)])
            else:  # too large to unroll: the mapped function, the times still constants
                zm, pm = ca.MX.sym("z", self.nx, grid.size), ca.MX.sym("p", self.np)
                one = ca.Function("run", [zm, pm], [over_time(times, zm, pm)])
            self._maps[key] = one.map(runs, "thread", threads)
        return self._maps[key]

    # -- equilibrium -------------------------------------------------------
    def trim(
        self,
        p: np.ndarray,
        *,
        t: float = 0.0,
        x_guess: np.ndarray | None = None,
        tol: float = 1e-9,
        free: Sequence[str] = (),
        steady_motion: bool = True,
    ) -> dict[str, float]:
        """Equilibrium :math:`f(t, x, p) = 0` for the inputs at time ``t``.

        Solved by trust-region least squares on the scaled states with the exact
        Jacobian, from ``x_guess`` (default: the parameter-based initial state).
        Where the equilibrium is not unique (a free integrator, such as an
        open-loop cylinder), the solution nearest the guess is returned.

        ``free`` names states that keep their guessed value and whose rates need
        not vanish: with a piston's position free, the trim is the *steady
        motion* of an open-loop drive (constant speed, pressures and spool).
        That the free states then move steadily is checked unless
        ``steady_motion`` is False (the free states are measured values, held
        while the others settle).

        Raises
        ------
        TrimError
            If the residual does not fall below ``tol`` (scaled rates, 1/s).
        """
        from scipy.optimize import least_squares  # SciPy's optimiser is imported where it is used: import stays fast

        p = np.asarray(p, dtype=float)
        x = np.asarray(self.x0(p), dtype=float).ravel() if x_guess is None else np.asarray(x_guess, dtype=float)
        unknown_free = [n for n in free if n not in self.state_names]
        if unknown_free:
            raise TrimError(f"trim of {self.name!r}: free = {unknown_free[0]!r} is not a state{did_you_mean(unknown_free[0], self.state_names)}; "
                            f"states: {', '.join(self.state_names)}")
        solved = np.array([n not in free for n in self.state_names], dtype=bool)
        if self.nx == 0:
            return {}
        if not solved.any():
            raise TrimError(f"trim of {self.name!r}: every state is free; nothing to solve for")
        z0 = x / self.nominal

        def full(zs: np.ndarray) -> np.ndarray:
            z = z0.copy()
            z[solved] = zs
            return z

        def res(zs: np.ndarray) -> np.ndarray:
            r: np.ndarray = np.asarray(self._fz(t, full(zs), p), dtype=float).ravel()
            rs: np.ndarray = r[solved]
            return rs

        def jac(zs: np.ndarray) -> np.ndarray:
            J: np.ndarray = np.asarray(self._jz(t, full(zs), p), dtype=float)
            Js: np.ndarray = J[np.ix_(solved, solved)]
            return Js

        sol = least_squares(res, z0[solved], jac=jac, method="trf", xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=2000)
        r = res(sol.x)
        names = [n for n, keep in zip(self.state_names, solved) if keep]
        worst = int(np.argmax(np.abs(r))) if r.size else 0
        if r.size and (
            not np.all(np.isfinite(r)) or np.abs(r[worst]) > tol * max(1.0, np.abs(res(z0[solved])).max())
        ):
            nominal = self.nominal[solved][worst]
            raise TrimError(
                f"no equilibrium found for {self.name!r}: the largest remaining rate is in "
                f"{names[worst]} ({r[worst] * nominal:.3g} {si_unit(self.units[names[worst]])}/s)"
            )
        z = full(sol.x)
        why = self.unconverged(np.array([t]), z[:, None], p)
        if why is not None:
            raise TrimError(f"no equilibrium found for {self.name!r}: {why}")
        if free and steady_motion:
            # a steady motion: the free states' rates must be constant too (d/dt f = J f = 0), or it is no steady state
            fz = np.asarray(self._fz(t, z, p), dtype=float).ravel()
            Jz = np.asarray(self._jz(t, z, p), dtype=float)
            change = Jz @ fz
            scale = np.abs(Jz).max() * np.abs(fz).max()
            k = int(np.argmax(np.abs(change)))
            if scale > 0 and abs(change[k]) > 1e-6 * scale:
                raise TrimError(
                    f"trim of {self.name!r} with {', '.join(free)} free: no steady motion; the rate of "
                    f"{self.state_names[k]} keeps changing ({change[k] * self.nominal[k]:.3g} {si_unit(self.units[self.state_names[k]])}/s²)"
                )
        return dict(zip(self.state_names, (z * self.nominal).tolist()))

    def linearize(self, x: np.ndarray | Mapping[str, float], p: np.ndarray, t: float = 0.0) -> np.ndarray:
        """Exact Jacobian :math:`A = \\partial f/\\partial x` at ``(t, x, p)`` (SI)."""
        if isinstance(x, Mapping):
            x = np.array([x[n] for n in self.state_names])
        return np.asarray(self.jac_x(t, x, p), dtype=float)

    # -- periodic orbits -------------------------------------------------------
    def periodic(
        self,
        p: np.ndarray,
        period: float,
        *,
        n_points: int = 129,
        x_guess: np.ndarray | None = None,
        settle_periods: int = 1,
        tol: float = 1e-5,
        accept: float | None = None,
        max_iter: int = 40,
        rtol: float = 1e-7,
        atol: float = 1e-9,
        max_steps: int = 1_000_000,
    ) -> tuple[np.ndarray, np.ndarray, float]:
        r"""The periodic orbit of a system driven with ``period`` [s]: states (SI) at ``n_points`` times over it.

        Shooting, with the stiff integrator: from ``x_guess`` (default: the parameter-based initial state),
        after ``settle_periods`` plain periods, the map :math:`\Phi` (one period of CVODES, on states scaled by
        their nominal magnitudes) is iterated while it contracts (each period at most 0.6 times the last
        mismatch); where it does not (a slowly decaying drift), a Newton step (at most four) on :math:`\Phi(z_0) = z_0` with the
        Jacobian from CVODES' forward sensitivities. The drive must repeat with ``period`` from t = 0.
        ``tol`` bounds the mismatch of the orbit found, in nominal magnitudes of the states; with ``accept``,
        the best orbit found in ``max_iter`` iterations is returned if its mismatch is below ``accept``
        (a drive that makes the system hit a stop converges slowly: its orbit is still as good as that).

        Returns
        -------
        (t, X, mismatch)
            The times [s] from 0 to ``period``, the states there (rows: states), and how far one period
            moves the orbit's start (in nominal magnitudes).

        Raises
        ------
        SolverError
            If the mismatch :math:`\|\Phi(z_0) - z_0\|_\infty` does not fall below ``tol`` in ``max_iter``
            iterations, or the integrator fails.
        """
        if not (np.isfinite(period) and period > 0):
            raise ParameterError(f"period = {period!r} s: expected a positive duration")
        settings = SolverSettings(rtol, atol, max_steps)
        grid = np.linspace(0.0, float(period), int(n_points))
        p = self._check_parameters(p)
        key = ("periodic", grid.tobytes(), rtol, atol, max_steps)
        if key not in self._integrators:
            integ = self._integrator(grid, settings)
            z0, pp = ca.MX.sym("z0", self.nx), ca.MX.sym("p", self.np)
            end = integ(x0=z0, p=pp)["xf"][:, -1]
            self._integrators[key] = ca.Function("shoot", [z0, pp], [end, ca.jacobian(end, z0)])
        shoot, integ = self._integrators[key], self._integrator(grid, settings)
        if x_guess is not None and np.asarray(x_guess).shape != (self.nx,):
            raise ParameterError(f"x_guess: {np.asarray(x_guess).shape} values; expected {self.nx} states")
        z = (np.asarray(self.x0(p), dtype=float).ravel() if x_guess is None else np.asarray(x_guess, dtype=float)) / self.nominal
        where = f"periodic orbit of {self.name!r} (period {period:.6g} s)"

        def one_period(z: np.ndarray) -> np.ndarray:
            return np.asarray(integ(x0=z, p=p)["xf"], dtype=float)

        try:
            with captured():
                for _ in range(settle_periods):
                    z = one_period(z)[:, -1]
                best: tuple[float, np.ndarray, np.ndarray] | None = None  # mismatch, start, orbit
                previous, plain, newton = np.inf, 0, 0
                for _ in range(max_iter):
                    Z = one_period(z)
                    r = Z[:, -1] - z
                    size = float(np.max(np.abs(r)))
                    if not np.isfinite(size):
                        raise SolverError(f"{where}: the states became NaN/Inf over a period")
                    if best is not None and size > best[0] and plain == 0:  # the Newton step made it worse
                        z, plain = best[1], 3  # back to the best start, and a few plain periods from there
                        continue
                    if best is None or size < best[0]:
                        best = (size, z, Z)
                    if size < tol:
                        break
                    if plain == 0 and size > 0.6 * previous and newton < 4:  # plain periods converge slowly: Newton
                        newton += 1
                        J = np.asarray(shoot(z, p)[1], dtype=float)
                        try:
                            z = z - np.linalg.solve(J - np.eye(self.nx), r)
                        except np.linalg.LinAlgError:
                            z = Z[:, -1]
                        previous = np.inf
                        continue
                    plain = max(plain - 1, 0)
                    previous, z = size, Z[:, -1]
        except SolverError:
            raise
        except RuntimeError as exc:
            raise SolverError(f"{where}: {translate(str(exc))}") from None
        assert best is not None
        mismatch, z, Z = best
        if mismatch >= (tol if accept is None else max(tol, accept)):
            raise SolverError(
                f"{where} not found: after {max_iter} iterations one period still moves the states by "
                f"{mismatch:.3g} of their nominal magnitudes (accepted: {tol:g}); the response may not be "
                "periodic (a subharmonic, or a drift slower than the iterations)"
            )
        why = self.unconverged(grid, Z, p)
        if why is not None:
            raise SolverError(f"{where}: {why}")
        return grid, Z * self.nominal[:, None], mismatch

    # -- batch ---------------------------------------------------------------
    def batch(
        self,
        t_end: float,
        p_base: np.ndarray,
        sets: Mapping[str, Sequence[float] | np.ndarray],
        *,
        n_points: int = 201,
        t_eval: Sequence[float] | None = None,
        rtol: float | None = None,
        atol: float | None = None,
        max_steps: int | None = None,
        threads: int | None = None,
        failed: Mapping[int, str] | None = None,
        progress: Callable[[int, int], None] | bool | None = None,
        accuracy: float | None = None,
        method: str = DEFAULT_METHOD,
        events: bool = True,
    ) -> BatchResult:
        """Run the model once per parameter set, the integrator mapped over the sets.

        ``sets`` maps parameter names to equally long sequences of SI values;
        other parameters keep ``p_base``. Runs are spread over ``threads``
        threads (default: all cores). Initial states follow the parameters.
        Outputs other than states are computed when first accessed.

        Each run succeeds or fails on its own: a run that fails (or that
        ``failed`` already marks as invalid, index -> reason) has NaN signals
        and its reason in :attr:`BatchResult.failed`; the others keep their
        results. Runs go in chunks; a chunk in which a run fails is split until
        the failing runs are isolated. ``progress=True`` shows a progress bar (tqdm: a terminal's or a
        notebook's); a callable ``progress(done, total)`` is called after
        every chunk. Tolerances, ``accuracy``, ``method`` and ``events`` as in :meth:`simulate`; a compiled method runs
        each set on a thread of its own, the interpreter's lock released while it integrates.
        """
        grid = output_grid(t_end, t_eval, n_points)
        method = self._resolve(check_method(method))
        settings = SolverSettings.of(rtol, atol, accuracy, max_steps, method=method)
        if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int) or threads < 1):
            raise ParameterError(f"threads = {threads!r}: expected a whole number of threads, at least 1")
        P = self._batch_parameters(self._check_parameters(p_base), sets)
        n, nt = P.shape[1], grid.size
        failures = {int(k): str(v) for k, v in (failed or {}).items()}
        good = np.array([i not in failures for i in range(n)])
        X0 = np.full((self.nx, n), np.nan)
        if good.any() and self.nx:  # a model without states (pure functions of its parameters) has no x0
            X0[:, good] = np.asarray(self.x0.map(int(good.sum()))(P[:, good]), dtype=float).reshape(self.nx, -1)
        for j in np.flatnonzero(good & ~np.all(np.isfinite(X0), axis=0)).tolist():
            bad = [nm for nm, v in zip(self.state_names, X0[:, j]) if not np.isfinite(v)]
            failures[j] = f"initial state not finite in {', '.join(bad)}"
        if self.algebraic_names:
            for j in range(n):
                why = None if j in failures else self.unconverged(grid[:1], X0[:, j : j + 1] / self.nominal[:, None], P[:, j])
                if why is not None:
                    failures[j] = f"cannot start: {why}"
        todo = [i for i in range(n) if i not in failures]
        nthreads = threads or os.cpu_count() or 1
        X = np.empty((self.nx, n, nt))  # every run is written by its chunk (SI), or set to NaN as failed below
        chunks: list[tuple[list[int], np.ndarray]] = []  # the runs integrated together, and their scaled states
        start = time.perf_counter()
        if self.nx == 0:
            X = np.zeros((0, n, nt))
        else:
            if method != "cvodes":  # each run on a thread of its own: larger chunks cost nothing

                def solve(part: list[int]) -> None:
                    self._compiled_runs(method, grid, settings, part, X0, P, X, failures, nthreads, chunks, events)

                chunk = max(4 * nthreads, min(256, len(todo)))
            else:
                integ = self._integrator(grid, settings)

                def solve(part: list[int]) -> None:
                    self._solve_runs(integ, part, X0 / self.nominal[:, None], P, X, failures, nthreads, chunks)

                chunk = max(4 * nthreads, min(64, len(todo)))
            done = len(failures)
            report, bar = _progress_of(progress, n, self.name)
            try:
                with interruptible():  # Ctrl-C stops the runs on every thread (compiled) or CVODES' map
                    for c0 in range(0, len(todo), chunk):
                        part = todo[c0 : c0 + chunk]
                        solve(part)
                        done += len(part)
                        if report is not None:
                            report(done, n)
            except KeyboardInterrupt:
                raise Interrupted(f"batch of {self.name!r} ({method}; {done} of {n} runs done)") from None
            finally:
                if bar is not None:
                    bar.close()
        wall = time.perf_counter() - start
        for i in todo:
            if i not in failures and not np.all(np.isfinite(X[:, i])):
                k = int(np.argmax(~np.all(np.isfinite(X[:, i]), axis=0)))
                bad = [nm for nm, v in zip(self.state_names, X[:, i, k]) if not np.isfinite(v)]
                failures[i] = f"the solution became NaN/Inf at t = {grid[k]:.6g} s in {', '.join(bad)}"
            elif i not in failures and self.algebraic_names:
                why = self.unconverged(grid, X[:, i] / self.nominal[:, None], P[:, i])
                if why is not None:
                    failures[i] = why
        for i in failures:
            X[:, i] = np.nan
        data = {name: X[j] for j, name in enumerate(self.state_names)}
        if self.nx == 0:  # nothing integrated: the outputs of each run from its parameters
            chunks = [(todo, np.zeros((0, len(todo) * nt)))] if todo else []

        def outputs(names: Sequence[str]) -> dict[str, np.ndarray]:
            """``names`` of every run, each chunk of runs in one threaded call on the integrator's matrix."""
            Y = np.empty((len(names), n, nt))  # every run is written by its chunk, or set to NaN as failed
            for runs, Z in chunks:
                fy = self._over_runs(tuple(names), self._output_function(names, nt), self._output_size(names), grid,
                                     len(runs), nthreads)  # fmt: skip
                values, code = _buffered(fy, {0: Z, 1: P[:, runs]})
                if code != 0:
                    raise RuntimeError(f"batch of {self.name!r}: the outputs {', '.join(names)} could not be evaluated")
                Y[:, runs, :] = values.reshape(-1, len(runs), nt)
            Y[:, sorted(failures), :] = np.nan
            return {name: Y[j] for j, name in enumerate(names)}

        params = {name: P[j] for j, name in enumerate(self.parameter_names)}
        implausible = self._batch_plausibility(grid, X, P, chunks, failures, nthreads)
        stats = {
            "wall_time_s": wall,
            "method": method,
            "rtol": settings.rtol,
            "atol": settings.atol,
            "runs": n,
            "failed": len(failures),
            "implausible": len(implausible),
            "threads": nthreads,
        }
        result = BatchResult(
            grid,
            data,
            dict(self.units),
            params,
            stats,
            self.name,
            outputs,
            dict(sorted(failures.items())),
            varied=list(sets),
            param_units=dict(self.parameter_units),
            pending=self.output_names,
        )
        result.warnings = implausible
        if implausible:
            warnings.warn(
                f"batch of {self.name!r}: {len(implausible)} of {n} runs physically implausible "
                f"(first, run {min(implausible)}: {implausible[min(implausible)][0]}); see BatchResult.warnings",
                ImplausibleResultWarning,
                stacklevel=3,
            )
        return result

    def _batch_plausibility(
        self,
        grid: np.ndarray,
        X: np.ndarray,
        P: np.ndarray,
        chunks: list[tuple[list[int], Any]],
        failures: Mapping[int, str],
        threads: int,
    ) -> dict[int, list[Implausible]]:
        """The physical bounds each run of a batch crossed; the watched signals that are not states are
        computed a chunk at a time on the integrator's matrix."""
        if not self.watched:
            return {}
        nt = grid.size
        found: dict[int, list[Implausible]] = {}
        for runs, Z in chunks:
            per_time = self._limit_values.n_instructions() + 2 * len(self.watched)
            fe = self._over_runs("extremes", self._limit_extremes(nt), per_time, grid, len(runs), threads)
            E, code = _buffered(fe, {0: Z, 1: P[:, runs]})  # [min, max] of each run, side by side
            if code != 0:
                raise RuntimeError(f"batch of {self.name!r}: the plausibility checks could not be evaluated")
            lows, highs = (np.asarray(b, dtype=float) for b in self.limit_bounds.map(len(runs))(P[:, runs]))
            for j, k in enumerate(runs):
                extremes = E[:, 2 * j : 2 * j + 2]
                if k not in failures and check(grid[[0, -1]], self.watched, extremes, lows[:, j], highs[:, j]):
                    found[k] = self.plausibility(grid, X[:, k, :], P[:, k])
        return dict(sorted(found.items()))

    def _batch_parameters(self, p_base: np.ndarray, sets: Mapping[str, Sequence[float] | np.ndarray]) -> np.ndarray:
        """The parameter matrix (parameters x runs) of a batch."""
        columns, n = batch_columns(sets)
        P = np.tile(p_base[:, None], (1, n))
        for name, vals in columns.items():
            if name not in self.parameter_names:
                raise ParameterError(f"batch: unknown parameter {name!r} of {self.name!r}")
            try:
                P[self.parameter_names.index(name)] = np.asarray(vals, dtype=float)
            except (TypeError, ValueError):
                raise ParameterError(f"batch: {name}: expected numbers (SI), one per run") from None
        return P

    def _solve_runs(
        self,
        integ: ca.Function,
        runs: list[int],
        Z0: np.ndarray,
        P: np.ndarray,
        X: np.ndarray,
        failures: dict[int, str],
        nthreads: int,
        chunks: list[tuple[list[int], Any]],
    ) -> None:
        """Integrate ``runs`` together; if one fails, halve until it stands alone and record why.

        Each group of runs integrated together is added to ``chunks`` with the integrator's matrix of their
        scaled states, from which their outputs are read."""
        size = len(runs)
        key = (id(integ), size, min(nthreads, size))
        if key not in self._batch_maps:
            self._batch_maps[key] = integ.map(size, "thread", key[2])
        mapped = self._batch_maps[key]
        with interruptible() as stop, captured() as printed:
            xf, code = _buffered(mapped, {mapped.index_in("x0"): Z0[:, runs], mapped.index_in("p"): P[:, runs]})
        if code != 0 and _interrupted(stop, "", printed.getvalue()):
            raise KeyboardInterrupt  # not a failure of these runs: the batch says how far it got
        if code != 0:
            if size == 1:  # the reason, from the integrator's own error
                try:
                    with captured():
                        integ(x0=Z0[:, runs], p=P[:, runs])
                    failures[runs[0]] = "the integrator stopped (no reason given)"
                except RuntimeError as exc:
                    failures[runs[0]] = translate(str(exc))
                return
            half = math.ceil(size / 2)
            self._solve_runs(integ, runs[:half], Z0, P, X, failures, nthreads, chunks)
            self._solve_runs(integ, runs[half:], Z0, P, X, failures, nthreads, chunks)
            return
        X[:, runs, :] = xf.reshape(self.nx, size, -1) * self.nominal[:, None, None]  # unscaled as they arrive
        chunks.append((list(runs), xf))

    def _compiled_runs(
        self,
        method: str,
        grid: np.ndarray,
        settings: SolverSettings,
        runs: list[int],
        X0: np.ndarray,
        P: np.ndarray,
        X: np.ndarray,
        failures: dict[int, str],
        nthreads: int,
        chunks: list[tuple[list[int], Any]],
        events: bool,
    ) -> None:
        """Integrate ``runs`` with a compiled method, ``nthreads`` at a time (each on its own C instance, the
        interpreter's lock released in C); the runs that succeed are added to ``chunks`` as one matrix of
        scaled states, as :meth:`_solve_runs` adds them."""
        from concurrent.futures import ThreadPoolExecutor

        solver = self._compiled_solvers(method)

        def one(i: int) -> tuple[int, np.ndarray, str | None]:
            Xi, _, failure, _, _ = solver.integrate(
                P[:, i], X0[:, i], grid, method=method, rtol=settings.rtol, atol=settings.atol,
                max_steps=settings.max_steps, events=events,
            )  # fmt: skip
            return i, Xi, failure

        with interruptible():  # armed here on the main thread: the runs on the pool's threads read its flag
            pool = ThreadPoolExecutor(max_workers=max(1, min(nthreads, len(runs))))
            try:
                finished = list(pool.map(one, runs))
            finally:  # on Ctrl-C: the runs not started are dropped, the running ones stop within a step
                pool.shutdown(wait=True, cancel_futures=True)
        good = []
        for i, Xi, failure in finished:
            if failure is not None:
                failures[i] = f"{method}: {failure}"
            else:
                X[:, i, :] = Xi
                good.append(i)
        if good:
            Z = (X[:, good, :] / self.nominal[:, None, None]).reshape(self.nx, -1)
            chunks.append((good, Z))

    # -- forward sensitivities ---------------------------------------------
    def _sensitivity_integrator(self, grid: np.ndarray, settings: SolverSettings, columns: tuple[int | None, ...]) -> ca.Function:
        """CVODES on the states and their sensitivities to ``len(columns)`` directions, in scaled form.

        The sensitivity equations :math:`\\dot S = \\partial f/\\partial z\\, S + \\partial f/\\partial p_k\\, d_k`
        are built from the model's own graph (exact derivatives), so CVODES integrates them with the states under
        one error control. Column ``k`` is driven by parameter ``columns[k]`` scaled by ``d_k`` (an extra
        parameter of the integrator), or by nothing (``None``: a direction of the initial state only).
        """
        steps = settings.steps_per_interval(grid.size - 1)
        key = ("sens", grid.tobytes(), settings.rtol, settings.atol, steps, columns)
        if key not in self._integrators:
            self._make_room()
            z, t, p, fz = self._dae["x"], self._dae["t"], self._dae["p"], self._dae["ode"]
            n = len(columns)
            S = ca.SX.sym("S", self.nx, n)
            d = ca.SX.sym("d", n)
            Jz = ca.jacobian(fz, z)
            Jp = ca.jacobian(fz, p)
            forcing = ca.horzcat(*[Jp[:, c] * d[k] if c is not None else ca.SX.zeros(self.nx, 1) for k, c in enumerate(columns)])
            dS = ca.mtimes(Jz, S) + forcing
            dae = {"x": ca.vertcat(z, ca.vec(S)), "t": t, "p": ca.vertcat(p, d), "ode": ca.vertcat(fz, ca.vec(dS))}
            opts = {"abstol": settings.atol, "reltol": settings.rtol, "max_num_steps": steps}
            self._integrators[key] = ca.integrator("sens", "cvodes", dae, float(grid[0]), [float(g) for g in grid], opts)
        return self._integrators[key]

    def initial_jacobian(self, p: np.ndarray) -> np.ndarray:
        """:math:`\\partial x_0/\\partial p` of the parameter-based initial state (SI), ``nx`` by ``np``."""
        key = "x0_jac"
        if key not in self._maps:
            ps = ca.SX.sym("p", self.np)
            self._maps[key] = ca.Function("x0_jac", [ps], [ca.densify(ca.jacobian(self.x0(ps), ps))])
        return np.asarray(self._maps[key](p), dtype=float).reshape(self.nx, self.np)

    def parameter_jacobian(self, t: float, x: np.ndarray, p: np.ndarray) -> np.ndarray:
        """:math:`\\partial f/\\partial p` at ``(t, x, p)`` (SI), ``nx`` by ``np``."""
        key = "f_p"
        if key not in self._maps:
            ts, xs, ps = ca.SX.sym("t"), ca.SX.sym("x", self.nx), ca.SX.sym("p", self.np)
            self._maps[key] = ca.Function("f_p", [ts, xs, ps], [ca.densify(ca.jacobian(self.f(ts, xs, ps), ps))])
        return np.asarray(self._maps[key](t, x, p), dtype=float).reshape(self.nx, self.np)

    def sensitivities(
        self,
        grid: np.ndarray,
        p: np.ndarray,
        x0: np.ndarray,
        dx0: np.ndarray,
        columns: Sequence[int | None],
        scale: Sequence[float],
        settings: SolverSettings,
    ) -> tuple[np.ndarray, np.ndarray]:
        """States and their exact derivatives along ``len(columns)`` directions, at the times ``grid``.

        Direction ``k`` changes parameter ``columns[k]`` by ``scale[k]`` per unit (``None``: no parameter) and
        the initial state by ``dx0[:, k]`` (SI). Returns ``X`` (SI, ``nx`` by ``nt``) and ``S`` (``nt`` by ``nx``
        by ``len(columns)``, SI per unit of each direction).

        Raises
        ------
        SolverError
            If the integration fails (the reason, in CVODES' words translated).
        """
        p = self._check_parameters(p)
        n = len(columns)
        integ = self._sensitivity_integrator(np.asarray(grid, dtype=float), settings, tuple(columns))
        nominal = self.nominal[:, None]
        start = np.concatenate([np.asarray(x0, dtype=float) / self.nominal, (np.asarray(dx0, dtype=float) / nominal).ravel(order="F")])
        scale_vec = np.asarray([s if c is not None else 0.0 for c, s in zip(columns, scale)], dtype=float)
        try:
            with interruptible() as stop, captured() as printed:
                args = {integ.index_in("x0"): start, integ.index_in("p"): np.concatenate([p, scale_vec])}
                out, _ = _buffered(integ, args, raises=True)
        except RuntimeError as exc:
            t_fail, _ = failure_point(printed.getvalue())
            if _interrupted(stop, str(exc), printed.getvalue()):
                raise Interrupted(f"sensitivities of {self.name!r} (cvodes)", t_fail, float(grid[-1])) from None
            where = f" at t = {t_fail:.6g} s" if t_fail is not None else ""
            raise SolverError(f"integration of {self.name!r} with its sensitivities failed{where}: {translate(str(exc))}") from None
        nt = out.shape[1]
        X = out[: self.nx] * nominal
        S = out[self.nx :].reshape(self.nx, n, nt, order="F").transpose(2, 0, 1) * self.nominal[None, :, None]
        if not (np.isfinite(X).all() and np.isfinite(S).all()):
            raise SolverError(f"integration of {self.name!r} with its sensitivities: the solution became NaN or Inf")
        return X, S

    def output_sensitivities(
        self, names: Sequence[str], grid: np.ndarray, X: np.ndarray, S: np.ndarray, p: np.ndarray,
        columns: Sequence[int | None], scale: Sequence[float],
    ) -> tuple[np.ndarray, np.ndarray]:
        """Outputs ``names`` (in :attr:`units`) at the times ``grid`` and their derivatives along the directions of
        :meth:`sensitivities` (whose ``X`` and ``S`` they take): ``(Y, dY)``, ``len(names)`` by ``nt`` and ``nt`` by
        ``len(names)`` by ``len(columns)``."""
        key = ("out_sens", tuple(names), tuple(columns))
        if key not in self._maps:
            t, x, ps = ca.SX.sym("t"), ca.SX.sym("x", self.nx), ca.SX.sym("p", self.np)
            n = len(columns)
            Sx, d = ca.SX.sym("S", self.nx, n), ca.SX.sym("d", n)
            y = self.outputs(t, x, ps)
            idx = [self._output_index[nm] for nm in names]
            ysel = ca.vertcat(*[y[i] for i in idx])
            Jp = ca.jacobian(ysel, ps)
            direct = ca.horzcat(*[Jp[:, c] * d[k] if c is not None else ca.SX.zeros(len(idx), 1) for k, c in enumerate(columns)])
            dy = ca.mtimes(ca.jacobian(ysel, x), Sx) + direct
            self._maps[key] = ca.Function("y_sens", [t, x, ps, Sx, d], [ca.densify(ysel), ca.densify(ca.vec(dy))])
        fn = self._maps[key]
        nt, m, n = grid.size, len(names), len(columns)
        mapped = fn.map(nt)
        scale_vec = np.asarray([s if c is not None else 0.0 for c, s in zip(columns, scale)], dtype=float)
        Sflat = S.transpose(1, 2, 0).reshape(self.nx, n * nt, order="F")
        Y, dY = mapped(grid[None, :], X, np.repeat(p[:, None], nt, axis=1), Sflat, np.repeat(scale_vec[:, None], nt, axis=1))
        Y = np.asarray(Y, dtype=float).reshape(m, nt)
        dY = np.asarray(dY, dtype=float).reshape(m, n, nt, order="F").transpose(2, 0, 1)
        return Y, dY

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
