"""Integrator settings, checked once for every entry point, and what CVODES says translated.

The settings a user gives (tolerances, step budget, output grid) are checked
here before any integrator is built, so a bad one is refused with its name and
value instead of failing inside SUNDIALS. CVODES reports failures as return
flags and prints its own lines; :func:`captured` keeps those lines off the
user's terminal and :func:`translate` turns a flag into a sentence.

A run is stopped by Ctrl-C (SIGINT) within a step: :func:`interruptible` arms
the flag :data:`STOP` that the compiled solvers read before every step (CVODES
is stopped by CasADi, which runs Python's signal handler from its callbacks),
and the run raises :class:`Interrupted`, never a solver failure.
"""

from __future__ import annotations

import contextlib
import ctypes
import io
import math
import os
import re
import signal
import socket
import sys
import threading
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from hydroservo.errors import ParameterError, did_you_mean

__all__ = ["MAX_POINTS", "DEFAULT_ACCURACY", "DEFAULT_MAX_STEPS", "METHODS", "DEFAULT_METHOD", "AUTO_METHOD", "AUTO_MAX_STATES", "check_method", "default_max_steps", "tolerances", "SolverSettings", "output_grid", "batch_columns", "captured", "translate", "failure_point", "STOP", "Interrupted", "interruptible"]

#: Largest output grid [points]: 100 001 points of 20 signals are 16 MB; a million would be gigabytes.
MAX_POINTS = 100_001

#: Least number of steps CVODES may take between two output times, whatever the total budget.
MIN_STEPS_PER_INTERVAL = 500

#: Step budget of a run at rtol 1e-6 (accuracy 1e-4) and looser: the built-in models take 600 to 25 000 steps there.
DEFAULT_MAX_STEPS = 100_000
#: The compiled methods' default budget, this many times CVODES': their steps cost microseconds (100 000 of the
#: flight simulator's take 1 s), random valid sets whose valve chatters between its stops take up to 550 000, and
#: a run that is stuck fails within 10 000 steps whatever the budget (data/c/stepper.c, STUCK_STEPS).
COMPILED_STEPS_FACTOR = 10

_REASONS = {
    "CV_TOO_MUCH_WORK": "the step budget was used up (the dynamics are too fast for the time span, or a state diverges)",
    "CV_CONV_FAILURE": "the Newton corrector did not converge (a discontinuity or a singular Jacobian)",
    "CV_ERR_FAILURE": "the error test failed repeatedly (a discontinuity or a state blowing up)",
    "CV_TOO_CLOSE": "the output times are too close together",
    "CV_RHSFUNC_FAIL": "the right-hand side could not be evaluated (NaN or Inf)",
    "CV_REPTD_RHSFUNC_ERR": "the right-hand side repeatedly gave NaN or Inf",
    "CV_FIRST_RHSFUNC_ERR": "the right-hand side gave NaN or Inf at the initial state",
    "CV_UNREC_RHSFUNC_ERR": "the right-hand side gave NaN or Inf and the step could not be retried",
    "CV_LSETUP_FAIL": "the Jacobian could not be factorised (a singular or NaN Jacobian)",
    "CV_LSOLVE_FAIL": "the linear solve failed (a singular or NaN Jacobian)",
    "CV_TOO_MUCH_ACC": "the tolerances ask for more accuracy than floating point gives (loosen rtol or atol)",
}


#: The accuracy a run is integrated to unless asked otherwise: a deviation of at most about 1e-4 of the range of
#: each signal an engineer looks at (docs/engine.md, "Accuracy", has the deviations measured on the built-in models).
DEFAULT_ACCURACY = 1e-4
#: Accuracy per unit of relative tolerance, and relative tolerance per unit of absolute tolerance (on states
#: scaled by their nominal magnitude): measured on the built-in models, CVODES' deviation on their main signals
#: is 3 to 50 times rtol (about 400 times on the undamped limit cycle of Hopsan's Position Servo).
ACCURACY_PER_RTOL = 100.0
RTOL_PER_ATOL = 100.0


#: The same per method: the compiled variable-step methods of :mod:`hydroservo.system.native` control each
#: step's error as CVODES does; the global error of ros23 (of order 2) and dopri5 (riding its stability bound on
#: stiff circuits) grows more over a run, and 1000 meets the accuracy on the built-in models where 100 does not;
#: rodas3's meets it at 100, as CVODES's (benchmarks/bench_accuracy.py, docs/engine.md).
ACCURACY_PER_RTOL_OF = {"cvodes": ACCURACY_PER_RTOL, "ros23": 1000.0, "dopri5": 1000.0, "rodas3": 100.0}


def tolerances(accuracy: float, method: str = "cvodes") -> tuple[float, float]:
    """``(rtol, atol)`` for a wanted relative ``accuracy`` of the signals (of their range) with ``method``;
    ``1e-4`` gives the defaults of CVODES, ``(1e-6, 1e-8)``."""
    if not _real(accuracy) or not 1e-10 <= accuracy <= 0.1:
        raise ParameterError(
            f"accuracy = {accuracy!r}: expected a relative accuracy between 1e-10 and 0.1 (the default is "
            f"{DEFAULT_ACCURACY:g}, about 0.01 % of each signal's range)"
        )
    rtol = float(accuracy) / ACCURACY_PER_RTOL_OF.get(method, ACCURACY_PER_RTOL)
    return rtol, rtol / RTOL_PER_ATOL


#: The integration methods of a run: ``auto`` (the default: :data:`AUTO_METHOD` for a model of at most
#: :data:`AUTO_MAX_STATES` states where a C compiler is found, else CVODES), CVODES, and the compiled
#: variable-step methods of :mod:`hydroservo.system.native` (the same names as its ``ADAPTIVE_METHODS``).
METHODS = ("auto", "cvodes", "rodas3", "ros23", "dopri5")
DEFAULT_METHOD = "auto"
#: What ``auto`` runs where the model compiles: the L-stable Rosenbrock 3(2) of Sandu et al. on the exact
#: Jacobian, within the accuracy asked for on the built-in models (position-servo's relief flow apart) in 0.35 to
#: 0.8 of CVODES' time at the default accuracy (docs/engine.md, "Accuracy").
AUTO_METHOD = "rodas3"
#: ... for models of at most this many states: a Rosenbrock method evaluates and factorises the dense Jacobian at
#: every step, where CVODES reuses one over many steps, and the compiled Jacobian's code grows with its entries.
#: Measured on N flight-simulator loops in one model (benchmarks/bench_growth.py): rodas3 against CVODES 1.14x
#: faster at 10 states, 1.19x at 20, 0.89x at 30, 0.75x at 40, 0.16x at 240 (and 45 s to compile); larger models
#: run CVODES.
AUTO_MAX_STATES = 20


def check_method(method: str) -> str:
    """``method`` if it is one of :data:`METHODS`."""
    if method not in METHODS:
        raise ParameterError(
            f"method = {method!r}: expected one of {', '.join(METHODS)} (auto: the default, rodas3 for a model of at "
            f"most {AUTO_MAX_STATES} states where a C compiler is found, else cvodes; cvodes: BDF with error "
            "control, interpreted; rodas3: compiled Rosenbrock 3(2) for stiff circuits; ros23: compiled Rosenbrock "
            "2(3); dopri5: compiled Dormand-Prince 5(4), explicit)"
            + did_you_mean(str(method), METHODS)
        )
    return method


def default_max_steps(rtol: float) -> int:
    """The step budget of a run at ``rtol`` unless one is given: :data:`DEFAULT_MAX_STEPS` at 1e-6 and looser,
    growing as ``rtol^(-1/4)`` below (tenfold at 1e-10). A BDF method's steps grow as ``rtol^(-1/(q+1))`` at
    order q; measured on Hopsan's Position Servo, the most demanding built-in model, 24 800 steps at rtol 1e-6
    and 106 000 at 1e-10 (docs/engine.md)."""
    return int(DEFAULT_MAX_STEPS * max(1.0, (1e-6 / rtol) ** 0.25))


@dataclass(frozen=True)
class SolverSettings:
    """Tolerances and step budget of one run, checked on construction.

    ``rtol`` is relative; ``atol`` applies to states scaled by their nominal
    magnitude (so it is dimensionless). ``max_steps`` is the step budget of the
    whole run, shared out over the output intervals (each gets at least
    :data:`MIN_STEPS_PER_INTERVAL`): a hopeless set fails within about
    ``max_steps`` steps rather than ``max_steps`` per output point.
    """

    rtol: float = 1e-6
    atol: float = 1e-8
    max_steps: int = 100_000

    def __post_init__(self) -> None:
        rtol, atol, steps = self.rtol, self.atol, self.max_steps
        if not _real(rtol) or not 1e-14 <= rtol <= 0.1:
            raise ParameterError(
                f"rtol = {rtol!r}: expected a relative tolerance between 1e-14 and 0.1 (typically 1e-6)"
            )
        if not _real(atol) or not 0 < atol <= 1.0:
            raise ParameterError(
                f"atol = {atol!r}: expected an absolute tolerance above 0 and at most 1 "
                "(it applies to states scaled by their nominal magnitude; typically 1e-8)"
            )
        if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or not 100 <= steps <= 10**9:
            raise ParameterError(f"max_steps = {steps!r}: expected a whole number of steps from 100 to 1e9")

    @classmethod
    def of(
        cls, rtol: float | None = None, atol: float | None = None, accuracy: float | None = None,
        max_steps: int | None = None,
        method: str = "cvodes",
    ) -> SolverSettings:
        """The settings a caller asked for: an ``accuracy`` (:func:`tolerances`), or ``rtol`` and ``atol``;
        ``atol`` follows ``rtol`` (:data:`RTOL_PER_ATOL`) unless given; nothing given: :data:`DEFAULT_ACCURACY`;
        the step budget ``max_steps``, or :func:`default_max_steps` for the tolerance."""
        if accuracy is not None:
            if rtol is not None or atol is not None:
                raise ParameterError(
                    f"accuracy = {accuracy!r} with rtol = {rtol!r}, atol = {atol!r}: give an accuracy or tolerances, "
                    "not both"
                )
            rtol, atol = tolerances(accuracy, method)
        if rtol is None:
            rtol, default_atol = tolerances(DEFAULT_ACCURACY, method)
            atol = default_atol if atol is None else atol
        if atol is None:
            atol = rtol / RTOL_PER_ATOL if _real(rtol) else 1e-8
        if max_steps is None:
            max_steps = default_max_steps(rtol) if _real(rtol) and rtol > 0 else DEFAULT_MAX_STEPS
            if method != "cvodes":
                max_steps *= COMPILED_STEPS_FACTOR
        return cls(rtol, atol, max_steps)

    def steps_per_interval(self, n_intervals: int) -> int:
        """The most steps CVODES may take between two output times."""
        return max(MIN_STEPS_PER_INTERVAL, math.ceil(self.max_steps / max(n_intervals, 1)))


def _real(value: Any) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool) and math.isfinite(value)


def output_grid(t_end: float, t_eval: Sequence[float] | None, n_points: int) -> np.ndarray:
    """The output times: ``t_eval`` as given, or ``n_points`` equally spaced over [0, t_end]."""
    if t_eval is not None:
        try:
            grid = np.asarray(t_eval, dtype=float).ravel()
        except (TypeError, ValueError):
            raise ParameterError("t_eval: expected a sequence of times [s]") from None
        if not np.all(np.isfinite(grid)):
            k = int(np.argmax(~np.isfinite(grid)))
            raise ParameterError(f"t_eval[{k}] = {float(grid[k])}: expected finite times [s]")
        if grid.size < 2 or grid.size > MAX_POINTS:
            raise ParameterError(f"t_eval: {grid.size} times; expected 2 to {MAX_POINTS}")
        if np.any(np.diff(grid) <= 0):
            k = int(np.argmax(np.diff(grid) <= 0))
            raise ParameterError(
                f"t_eval[{k + 1}] = {grid[k + 1]:g} s after t_eval[{k}] = {grid[k]:g} s: expected strictly increasing times"
            )
        return grid
    if not _real(t_end) or not t_end > 0:
        raise ParameterError(f"t_end = {t_end!r} s: expected a positive, finite duration")
    if isinstance(n_points, bool) or not isinstance(n_points, (int, np.integer)) or not 2 <= n_points <= MAX_POINTS:
        raise ParameterError(f"n_points = {n_points!r}: expected a whole number from 2 to {MAX_POINTS}")
    return np.linspace(0.0, float(t_end), int(n_points))


def batch_columns(sets: Mapping[str, Any]) -> tuple[dict[str, list[Any]], int]:
    """The values of a batch per parameter, and the number of runs; refuses what is not a batch.

    A batch is a non-empty mapping of names to equally long, non-empty
    sequences (a string is a single value, not a sequence of characters).
    """
    if not sets:
        raise ParameterError("batch: no parameters to vary; give a mapping 'comp.param' -> sequence of values")
    columns: dict[str, list[Any]] = {}
    for name, vals in sets.items():
        if isinstance(vals, (str, bytes)) or not isinstance(vals, Iterable):
            raise ParameterError(f"batch: {name} = {vals!r}: expected a sequence of values, one per run")
        columns[name] = list(np.asarray(vals).ravel()) if isinstance(vals, np.ndarray) else list(vals)
    lengths = {k: len(v) for k, v in columns.items()}
    if len(set(lengths.values())) != 1:
        shown = ", ".join(f"{k}: {v}" for k, v in lengths.items())
        raise ParameterError(f"batch: the sequences must be equally long; got {shown}")
    n = next(iter(lengths.values()))
    if n == 0:
        raise ParameterError(f"batch: {', '.join(columns)}: empty sequences, no run to make")
    return columns, n


class _Router(io.TextIOBase):
    """A stream that writes to the calling thread's capture buffer, if it has one, else to the stream it replaced."""

    def __init__(self, original: Any) -> None:
        super().__init__()
        self.original = original
        self.local = threading.local()

    def write(self, text: str) -> int:
        buffer = getattr(self.local, "buffer", None)
        written: int = (buffer if buffer is not None else self.original).write(text)
        return written

    def flush(self) -> None:
        if getattr(self.local, "buffer", None) is None:
            self.original.flush()


_CAPTURE_LOCK = threading.Lock()
_captures = 0
_routers: tuple[_Router, _Router] | None = None


@contextlib.contextmanager
def captured() -> Iterator[io.StringIO]:
    """Collect what CasADi and CVODES print (they print through Python's streams) instead of showing it.

    Safe across threads (a calibration's starts run on several): while any thread captures, stdout and stderr
    are routers that send each thread's output to its own buffer, and the streams they replaced come back when
    the last capture ends. (``contextlib.redirect_stdout`` is not: two threads restoring in the wrong order
    leave the process writing into a dead buffer.)
    """
    global _captures, _routers
    buffer = io.StringIO()
    with _CAPTURE_LOCK:
        if _captures == 0:
            _routers = (_Router(sys.stdout), _Router(sys.stderr))
            sys.stdout, sys.stderr = _routers
        _captures += 1
        routers = _routers
    assert routers is not None
    outer = getattr(routers[0].local, "buffer", None)  # a capture inside a capture gives it back when done
    for router in routers:
        router.local.buffer = buffer
    try:
        yield buffer
    finally:
        for router in routers:
            router.local.buffer = outer
        with _CAPTURE_LOCK:
            _captures -= 1
            if _captures == 0:
                sys.stdout, sys.stderr = routers[0].original, routers[1].original
                _routers = None


def translate(message: str) -> str:
    """A sentence for the CVODES return flag in a CasADi error message."""
    flag = next((k for k in _REASONS if k in message), None)
    if flag is not None:
        return _REASONS[flag]
    lines = [line for line in message.strip().splitlines() if line.strip()]
    return "the integrator stopped: " + (lines[-1][:200] if lines else "no reason given")


_AT = re.compile(r"At t\s*=\s*([-+0-9.eE]+)(?:\s*,|\s+and\s+h\s*=\s*([-+0-9.eE]+))")


def failure_point(printed: str) -> tuple[float | None, float | None]:
    """Time and step size CVODES printed when it gave up ("At t = ... and h = ..."), if it did."""
    found = _AT.findall(printed)
    if not found:
        return None, None
    t, h = found[-1]
    try:
        return float(t), (float(h) if h else None)
    except ValueError:
        return None, None


# -- interrupts ------------------------------------------------------------------------------------------------

#: The stop flag of the compiled solvers (``NAME_set_stop`` in the exported C): nonzero while the runs under
#: :func:`interruptible` are to stop. Set by the watcher thread when SIGINT arrives, or when the thread that armed
#: the guard leaves it on a KeyboardInterrupt; cleared when a guard is armed.
STOP = ctypes.c_int(0)


class Interrupted(KeyboardInterrupt):
    """A run stopped by an interrupt (Ctrl-C, SIGINT): a :class:`KeyboardInterrupt` that says where.

    ``t`` is the time the run had reached [s] (None if not known), ``t_end`` the time it was to reach [s],
    ``what`` the run (e.g. "'position-servo' (rodas3, compiled)").
    """

    def __init__(self, what: str = "the run", t: float | None = None, t_end: float | None = None) -> None:
        self.what, self.t, self.t_end = what, t, t_end
        super().__init__(str(self))

    def __str__(self) -> str:
        if self.t is None:
            return f"{self.what} interrupted"
        end = "" if self.t_end is None else f" of {self.t_end:.6g} s"
        return f"{self.what} interrupted at t = {self.t:.6g} s{end}"


_GUARD_LOCK = threading.Lock()
_armed = 0  # guards entered on the main thread while the flag is armed
_previous_fd = -1  # the wakeup fd the outermost armed guard replaced (restored when it ends)
_pair: tuple[socket.socket, socket.socket] | None = None  # the watcher reads [0]; Python's handler writes [1]


def _watch(reader: socket.socket) -> None:
    """The watcher thread: Python's C-level signal handler writes each signal's number to the wakeup socket,
    also while the main thread is inside C with the interpreter's lock released; SIGINT sets :data:`STOP`.
    Bytes are passed on to the wakeup fd the guard replaced (an event loop's), so that it misses nothing."""
    while True:
        try:
            data = reader.recv(512)
        except OSError:
            return
        if not data:
            return
        if signal.SIGINT in data:
            STOP.value = 1
        forward = _previous_fd
        if forward != -1:
            with contextlib.suppress(OSError):
                os.write(forward, data)


def _arm() -> bool:
    """Point Python's signal wakeup at the watcher (main thread, lock held); False if it cannot be."""
    global _pair, _previous_fd
    if _pair is None:
        reader, writer = socket.socketpair()
        writer.setblocking(False)
        _pair = (reader, writer)
        threading.Thread(target=_watch, args=(reader,), name="hydroservo-interrupts", daemon=True).start()
    try:
        _previous_fd = signal.set_wakeup_fd(_pair[1].fileno(), warn_on_full_buffer=False)
    except (ValueError, OSError):
        return False
    return True


@contextlib.contextmanager
def interruptible() -> Iterator[ctypes.c_int | None]:
    """Runs inside stop on Ctrl-C: yields :data:`STOP` for the compiled solvers to read, or None where an
    interrupt cannot reach them.

    On the main thread, with Python's own SIGINT handler in place (the one that raises KeyboardInterrupt), the
    outermost guard clears the flag and points the signal wakeup (:func:`signal.set_wakeup_fd`) at a watcher
    thread that sets the flag when SIGINT arrives, and puts the wakeup it replaced back when it ends; guards
    inside it only count. On another thread (a batch's runs), it yields the flag while the main thread has one
    armed (the batch's caller waits inside it), else None: runs on threads of the user's own are not stopped.
    SIGINT ignored or handled by the user's own handler: None, nothing changed. A KeyboardInterrupt leaving the
    guard sets the flag, so that runs on other threads under it stop too.
    """
    global _armed, _previous_fd
    if threading.current_thread() is not threading.main_thread():
        yield STOP if _armed else None
        return
    outermost = counted = False
    with _GUARD_LOCK:
        if _armed:
            _armed += 1
            counted = True
        elif signal.getsignal(signal.SIGINT) is signal.default_int_handler and _arm():
            STOP.value = 0
            _armed, counted, outermost = 1, True, True
    try:
        yield STOP if counted else None
    except KeyboardInterrupt:
        if counted:
            STOP.value = 1
        raise
    finally:
        if counted:
            with _GUARD_LOCK:
                _armed -= 1
                if outermost:
                    with contextlib.suppress(ValueError, OSError):
                        signal.set_wakeup_fd(_previous_fd)
                    _previous_fd = -1
