"""Ctrl-C (SIGINT) stops a run within a step, says where, writes nothing and exits 130 (issue 37).

Each case runs the command line (or a script on the Python API) in a child process, waits until the child
has spent enough CPU time to be inside the solver, sends SIGINT, and measures the CPU time the child spends
after it (a hang guard by CPU time; the wall-clock time-out only catches a child that never ends). Before the
fix, the compiled solvers went on to the end of their integration (tens of seconds here) and the command
printed a traceback; CVODES' interrupted run was reported as a model failure after a second integration.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.system.integration import STOP, Interrupted, interruptible
from hydroservo.system.native import has_compiler

#: The child's CPU time [s] before SIGINT is sent: past the start (imports, model, compiled library from the
#: session's cache: about 0.6 s) and into the solver, far from the end of the run (its solver alone needs
#: more than 30 s of CPU for 10 000 s of position-servo with any method).
CPU_BEFORE_SIGNAL = 2.5

#: The most CPU time [s] a child may spend after SIGINT: a step, the message, the interpreter's exit.
CPU_AFTER_SIGNAL = 1.5

#: A child that has not ended this long [s] after SIGINT hangs (wall clock, generous for a loaded machine).
WALL_TIMEOUT = 120.0

LONG = ["--t-end", "10000", "--max-steps", "1000000000"]

needs_compiler = pytest.mark.skipif(not has_compiler(), reason="no C compiler")
needs_proc = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="CPU time read from /proc")


def _cpu(pid: int) -> float:
    """User + system CPU time [s] of the process ``pid`` so far (from /proc)."""
    with open(f"/proc/{pid}/stat", encoding="ascii") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _default_sigint() -> None:
    """In the child: SIGINT as an interactive shell leaves it (a test runner may have it ignored)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _interrupt(argv: list[str], cwd: Path) -> tuple[int, str, str, float]:
    """Run ``argv`` (a Python command line) in ``cwd``; SIGINT once it has used CPU_BEFORE_SIGNAL of CPU.
    Returns the exit code, stdout, stderr and the CPU time [s] it used after the signal."""
    out, err = cwd / "child.out", cwd / "child.err"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in sys.path if p)}
    with open(out, "w") as o, open(err, "w") as e:
        child = subprocess.Popen(argv, cwd=cwd, stdout=o, stderr=e, env=env, preexec_fn=_default_sigint)
    try:
        while child.poll() is None and _cpu(child.pid) < CPU_BEFORE_SIGNAL:
            time.sleep(0.02)
        assert child.poll() is None, f"the child ended before the signal: {err.read_text()[-2000:]}"
        before = _cpu(child.pid)
        child.send_signal(signal.SIGINT)
        deadline = time.monotonic() + WALL_TIMEOUT
        while time.monotonic() < deadline:
            pid, status, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                break
            time.sleep(0.02)
        else:
            pytest.fail(f"no end {WALL_TIMEOUT} s after SIGINT (CPU {_cpu(child.pid) - before:.1f} s since): a hang")
        child.returncode = os.waitstatus_to_exitcode(status)
        after = usage.ru_utime + usage.ru_stime - before
    finally:
        if child.returncode is None:
            child.kill()
            child.wait()
    stdout, stderr = out.read_text(), err.read_text()
    out.unlink()
    err.unlink()
    return child.returncode, stdout, stderr, after


def _warm(method: str) -> None:
    """The compiled library of position-servo for ``method`` in the session's cache (the child finds it)."""
    hs.load_model("position-servo").simulate(t_end=0.01, n_points=3, method=method)


@pytest.mark.slow  # a child process run into its solver and interrupted: a few seconds each
@needs_proc
@pytest.mark.parametrize(
    ("method", "span"),
    [
        pytest.param("auto", LONG, marks=needs_compiler),
        # dopri5 (explicit) is fast on this circuit but needs output times closer than 10 s to hold its steps
        pytest.param("dopri5", ["--t-end", "10000", "--points", "100001", "--max-steps", "1000000000"],
                     marks=needs_compiler),
        ("cvodes", LONG),
    ],
)  # fmt: skip
def test_ctrl_c_stops_simulate_exits_130_and_writes_nothing(method: str, span: list[str], tmp_path: Path) -> None:
    if method != "cvodes":
        _warm(method)
    out = tmp_path / "out"
    code, stdout, stderr, after = _interrupt(
        [sys.executable, "-m", "hydroservo", "simulate", "position-servo", *span, "--method", method, "--out", str(out)],
        tmp_path,
    )
    assert code == 130, stderr[-2000:]
    assert "Traceback" not in stderr, stderr[-2000:]
    shown = "rodas3" if method == "auto" else method
    lines = [line for line in stderr.splitlines() if line.startswith("hydroservo: ")]
    assert len(lines) == 1 and "error" not in lines[0], stderr[-2000:]
    assert f"simulation of 'position-servo' ({shown}" in lines[0] and "interrupted at t = " in lines[0], lines[0]
    assert "of 10000 s; nothing written" in lines[0], lines[0]
    assert "unstable" not in stderr and "failed" not in stderr
    assert stdout == ""
    assert not out.exists() and list(tmp_path.iterdir()) == []  # no folder, no staging left behind
    assert after < CPU_AFTER_SIGNAL, f"{after:.2f} s of CPU after SIGINT"


@pytest.mark.slow  # a child process run into its solver and interrupted: a few seconds each
@needs_proc
def test_ctrl_c_with_debug_shows_the_traceback(tmp_path: Path) -> None:
    code, _, stderr, _ = _interrupt(
        [sys.executable, "-m", "hydroservo", "--debug", "simulate", "position-servo", *LONG, "--method", "cvodes",
         "--write", "none"],
        tmp_path,
    )  # fmt: skip
    assert code != 0 and "Traceback" in stderr and "Interrupted" in stderr


_API_SCRIPT = """
import os, signal, sys, threading, time
import numpy as np
import hydroservo as hs
from hydroservo.system.integration import Interrupted

system = hs.load_model("position-servo")
what, method = sys.argv[1], sys.argv[2]
print("started", flush=True)
try:
    if what == "batch":
        system.batch({"load.m": np.linspace(100.0, 200.0, 8)}, 10000.0, method=method, max_steps=10**9, threads=2)
    elif what == "sensitivities":  # CVODES with forward sensitivities: calibration's integrations
        from hydroservo.system.integration import SolverSettings

        model = system.build()
        p = system._vector(model, None)
        x0 = np.asarray(model.x0(p), dtype=float).ravel()
        model.sensitivities(np.linspace(0.0, 10000.0, 1001), p, x0, np.zeros((model.nx, 1)),
                            [model.parameter_names.index("load.m")], [1.0], SolverSettings.of(max_steps=10**9))
    else:
        system.simulate(10000.0, method=method, max_steps=10**9)
except Interrupted as exc:
    print("Interrupted:", exc, flush=True)
else:
    print("not interrupted", flush=True)
"""


@pytest.mark.slow  # a child process run into its solver and interrupted: a few seconds each
@needs_proc
@pytest.mark.parametrize(
    ("what", "method"),
    [
        pytest.param("simulate", "rodas3", marks=needs_compiler),
        pytest.param("batch", "rodas3", marks=needs_compiler),
        ("simulate", "cvodes"),
        ("sensitivities", "cvodes"),
    ],
)
def test_ctrl_c_raises_interrupted_in_the_python_api(what: str, method: str, tmp_path: Path) -> None:
    if method != "cvodes":
        _warm(method)
    script = tmp_path / "run.py"
    script.write_text(textwrap.dedent(_API_SCRIPT), encoding="utf-8")
    code, stdout, stderr, after = _interrupt([sys.executable, str(script), what, method], tmp_path)
    assert code == 0, stderr[-2000:]
    said = stdout.splitlines()[-1]
    assert said.startswith("Interrupted:"), stdout
    if what == "batch":
        assert f"batch of 'position-servo' ({method}; 0 of 8 runs done) interrupted" in said, said
    elif what == "sensitivities":
        assert "sensitivities of 'position-servo' (cvodes) interrupted at t = " in said, said
    else:
        assert f"simulation of 'position-servo' ({method}" in said and "interrupted at t = " in said, said
    assert after < CPU_AFTER_SIGNAL, f"{after:.2f} s of CPU after SIGINT"


@needs_compiler
def test_the_compiled_solvers_stop_when_the_flag_is_set(monkeypatch: pytest.MonkeyPatch) -> None:
    """No signal: the flag alone, set from another thread, stops a compiled run at its next step."""
    monkeypatch.setattr(signal, "getsignal", lambda _: signal.default_int_handler)  # as in an interactive shell
    system = hs.load_model("position-servo")
    system.simulate(t_end=0.01, n_points=3, method="rodas3")
    setter = threading.Timer(0.3, lambda: setattr(STOP, "value", 1))
    start = time.process_time()
    with pytest.raises(Interrupted) as caught:
        with interruptible():
            setter.start()
            system.simulate(t_end=10000.0, method="rodas3", max_steps=10**9)
    setter.join()
    assert caught.value.t is not None and 0 < caught.value.t < 10000.0 and caught.value.t_end == 10000.0
    assert time.process_time() - start < 5.0  # the whole run would need more than 30 s
    assert isinstance(caught.value, KeyboardInterrupt)


def test_interruptible_restores_the_wakeup_fd(monkeypatch: pytest.MonkeyPatch) -> None:
    """The guard points Python's signal wakeup at its watcher and gives the previous one back."""
    if threading.current_thread() is not threading.main_thread():
        pytest.skip("signal wakeup is set from the main thread only")
    monkeypatch.setattr(signal, "getsignal", lambda _: signal.default_int_handler)
    previous = signal.set_wakeup_fd(-1)
    try:
        with interruptible() as stop:
            assert stop is STOP and STOP.value == 0
            with interruptible() as inner:  # nested: only counted
                assert inner is STOP
            ours = signal.set_wakeup_fd(-1)
            signal.set_wakeup_fd(ours, warn_on_full_buffer=False)
            assert ours != -1
        assert signal.set_wakeup_fd(-1) == -1
    finally:
        signal.set_wakeup_fd(previous)


@needs_compiler
def test_an_exported_stepper_stops_when_the_flag_is_set(monkeypatch: pytest.MonkeyPatch) -> None:
    """The fixed-step loop of the exported C (``NAME_run``) reads the same flag before every step."""
    from hydroservo.codegen.c import CStepper

    monkeypatch.setattr(signal, "getsignal", lambda _: signal.default_int_handler)
    stepper = CStepper(hs.load_model("flight-simulator"), step=1e-4, method="rk4")
    setter = threading.Timer(0.3, lambda: setattr(STOP, "value", 1))
    start = time.process_time()
    with pytest.raises(Interrupted) as caught:
        with interruptible():
            setter.start()
            stepper.advance(10**9)  # 1e5 s of steps: hours
    setter.join()
    assert caught.value.t is not None and caught.value.t > 0 and stepper.status == 0
    assert time.process_time() - start < 30.0
    STOP.value = 0
    stepper.advance(10)  # the instance goes on from where it stopped, outside the guard


#: calibrate's starts run on threads, where an integration cannot see the signal: each start stops at its next
#: evaluation of the residuals or their Jacobian (a Jacobian of the arm's records, with its sensitivities, takes
#: up to about a second of CPU on this machine), so the bound here is wider than a single run's
CPU_AFTER_SIGNAL_STARTS = 4.0


@pytest.mark.slow  # a child process run into its solver and interrupted: a few seconds each
@needs_proc
def test_ctrl_c_stops_calibrate_with_starts_on_threads(tmp_path: Path) -> None:
    """Exit 130, one message, nothing written. Before, the starts running when Ctrl-C came ran to their end (the
    pool waited for them): on this small example a start is short, so the CPU bound alone does not tell the two
    apart; test_a_start_stops_at_its_next_evaluation_once_the_flag_is_set does."""
    from hydroservo.data import example_files

    records = []
    for name, text in example_files().items():
        if name.startswith("arm_step"):
            (tmp_path / name).write_text(text, encoding="utf-8")
            records.append(name)
    out = tmp_path / "cal"
    argv = [sys.executable, "-m", "hydroservo", "calibrate", "robot-arm", "--record", ",".join(sorted(records)),
            "--input", "command.y", "--noise", "cyl.pA=0.05 bar,cyl.pB=0.05 bar,load.x=0.02 mm", "--starts", "32",
            "--out", str(out)]
    for name in ("spool.tau", "valve.c_v", "cyl.C_Li", "load.B", "load.F_c0"):
        argv += ["--fit", name]
    code, stdout, stderr, after = _interrupt(argv, tmp_path)
    assert code == 130, stderr[-2000:]
    assert "Traceback" not in stderr and "interrupted" in stderr, stderr[-2000:]
    assert not out.exists()
    assert after < CPU_AFTER_SIGNAL_STARTS, f"{after:.2f} s of CPU after SIGINT"


def test_a_start_stops_at_its_next_evaluation_once_the_flag_is_set() -> None:
    """A calibration start on a worker thread reads the guard's flag before each evaluation of its residuals and
    their Jacobian: set, it raises Interrupted there instead of fitting on."""
    import ctypes

    from hydroservo.identification import calibration as cal

    problem = cal._Problem([], [], {}, cal.SolverSettings.of())
    flag = ctypes.c_int(0)
    problem.stop = flag
    problem._check_stop()  # not set: nothing
    flag.value = 1
    with pytest.raises(Interrupted, match="calibration"):
        problem.residuals(np.zeros(0))
    with pytest.raises(Interrupted, match="calibration"):
        problem.jacobian(np.zeros(0))
