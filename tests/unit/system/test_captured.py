"""What CVODES prints is captured per thread, and the process's streams come back whatever the order threads
finish in (a calibration runs its starts on several threads)."""

from __future__ import annotations

import sys
import threading
import time

from hydroservo.system.integration import captured


def test_threads_capture_their_own_output_and_the_streams_come_back() -> None:
    stdout, stderr = sys.stdout, sys.stderr
    seen: dict[int, str] = {}
    first_in = threading.Event()

    def worker(k: int, hold: float) -> None:
        with captured() as buffer:
            if k == 0:
                first_in.set()
            print(f"thread {k}")
            time.sleep(hold)
            print(f"thread {k} again", file=sys.stderr)
        seen[k] = buffer.getvalue()

    slow = threading.Thread(target=worker, args=(0, 0.2))
    slow.start()
    first_in.wait()
    fast = threading.Thread(target=worker, args=(1, 0.0))  # enters after the slow one, leaves before it
    fast.start()
    fast.join()
    slow.join()
    assert seen[0] == "thread 0\nthread 0 again\n"
    assert seen[1] == "thread 1\nthread 1 again\n"
    assert sys.stdout is stdout and sys.stderr is stderr


def test_a_capture_inside_a_capture_hands_back() -> None:
    with captured() as outer:
        print("a")
        with captured() as inner:
            print("b")
        print("c")
    assert outer.getvalue() == "a\nc\n" and inner.getvalue() == "b\n"
