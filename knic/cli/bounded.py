"""Run a command's work under a wall-clock limit that covers everything: reading, parsing, planning.

A limit checked between steps cannot stop a parser or an engine that is busy inside one call (a 1.4 MB
problem spent two minutes in the PDDL reader). :func:`run_bounded` therefore runs the work in a forked
child process in its own process group and waits at most ``timeout`` seconds; on expiry the whole group
(the child and any engine subprocess it started, such as Fast Downward) is killed. The child hands back the
exit code and the text for stdout and stderr; the parent prints them, so callers (and tests capturing the
output) see the same output as without the limit.

Unix only (``os.fork``); elsewhere the work runs in-process without the limit.
"""

from __future__ import annotations

import io
import json
import math
import os
import select
import signal
import sys
import time
import traceback
from collections.abc import Callable
from contextlib import redirect_stderr, redirect_stdout, suppress

from core.errors import KnicError

#: exit status when the limit expires (as for a planner timeout)
EXIT_TIMEOUT = 1


def positive_seconds(value: float, option: str) -> float:
    """``value`` if it is a finite number of seconds above zero.

    Raises:
        KnicError: NaN, infinite, zero or negative (one line naming the option).
    """
    if not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise KnicError(f"{option} must be a finite number of seconds above 0, got {value!r}")
    return float(value)


def run_bounded(work: Callable[[], int], timeout: float, what: str) -> int:
    """Run ``work()`` (which prints and returns an exit code) with everything bounded by ``timeout`` seconds.

    A :class:`KnicError` in the work becomes its one-line message and exit code, as in :func:`knic.cli.main`;
    any other exception becomes one line ``internal error`` with exit code 1.
    """
    if not hasattr(os, "fork"):
        return work()
    read_end, write_end = os.pipe()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:  # child: own process group so that engine subprocesses die with it
        os.close(read_end)
        with suppress(OSError):
            os.setpgid(0, 0)
        payload = _child(work)
        with os.fdopen(write_end, "w", encoding="utf-8") as pipe:
            pipe.write(json.dumps(payload))
        os._exit(0)
    os.close(write_end)
    with suppress(OSError):
        os.setpgid(pid, pid)  # also from the parent: no race with the child's own call
    deadline = time.monotonic() + timeout
    chunks: list[bytes] = []
    timed_out = False
    with os.fdopen(read_end, "rb") as pipe:
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                timed_out = True
                break
            ready, _, _ = select.select([pipe], [], [], min(left, 1.0))
            if ready:
                chunk = os.read(pipe.fileno(), 1 << 16)
                if not chunk:
                    break
                chunks.append(chunk)
    if timed_out:
        _kill_group(pid)
        print(f"knic: error: {what} timed out after {timeout:g} s (--timeout)", file=sys.stderr)
        return EXIT_TIMEOUT
    os.waitpid(pid, 0)
    try:
        data = json.loads(b"".join(chunks).decode("utf-8"))
    except ValueError:
        print(f"knic: error: {what} ended without a result (the worker process died)", file=sys.stderr)
        return 1
    sys.stdout.write(data["out"])
    sys.stderr.write(data["err"])
    return int(data["code"])


def _child(work: Callable[[], int]) -> dict[str, object]:
    out, err = io.StringIO(), io.StringIO()
    try:
        with redirect_stdout(out), redirect_stderr(err):
            code = work()
    except KnicError as exc:
        err.write(f"knic: error: {exc}\n")
        code = exc.exit_code
    except RecursionError:
        err.write("knic: error: input nested too deeply\n")
        code = 2
    except BaseException as exc:
        last = traceback.extract_tb(exc.__traceback__)[-1:] or None
        where = f" at {last[0].filename}:{last[0].lineno}" if last else ""
        text = str(exc).replace("\n", " ")[:300]
        err.write(f"knic: error: internal error {type(exc).__name__}: {text}{where}\n")
        code = 1
    return {"code": code, "out": out.getvalue(), "err": err.getvalue()}


def _kill_group(pid: int) -> None:
    try:
        os.killpg(pid, signal.SIGKILL)
    except OSError:
        with suppress(OSError):
            os.kill(pid, signal.SIGKILL)
    with suppress(ChildProcessError):
        os.waitpid(pid, 0)
