"""Decoder passes in a forked worker process: pocketsphinx holds the GIL, so two passes of one utterance only
run side by side in two processes.

:class:`PassWorker` forks a child that keeps its parent's state as it was at the fork (decoders already
built, shared copy-on-write) and runs one job per request: a function of bytes whose result is JSON data.
Requests and replies go through two pipes, each message length-prefixed. A worker that died, or whose job
failed, answers None and the caller does the work itself. The child leaves when its request pipe closes:
:meth:`PassWorker.close`, the worker's garbage collection, the parent's exit or the parent's death.

Unix only (``os.fork``): elsewhere :func:`start_worker` gives None, and so it does in a process that already
runs other threads (a ROS executor, a web server): a fork there could copy a lock another thread holds, so
such a process decodes in itself.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import struct
import threading
import time
import weakref
from collections.abc import Callable
from typing import Any

_HEADER = struct.Struct("!Q")
#: the parent's ends of every open worker's pipes: a child forked later closes them, so that a worker still
#: sees its request pipe close when its parent closes it
_PARENT_ENDS: set[int] = set()
#: fork workers even when this process runs other threads (off: see the module docstring)
FORK_WITH_THREADS = False
#: how long :meth:`PassWorker.close` waits for the child to finish its job and leave before killing it (s)
CLOSE_WAIT = 5.0


class PassWorker:
    """A forked child running ``job`` on the bytes of each request (use :func:`start_worker`).

    Raises:
        OSError: the fork or the pipes failed.
    """

    def __init__(self, job: Callable[[bytes], Any]):
        requests_read, requests_write = os.pipe()
        replies_read, replies_write = os.pipe()
        try:
            pid = os.fork()
        except OSError:
            for fd in (requests_read, requests_write, replies_read, replies_write):
                os.close(fd)
            raise
        if pid == 0:  # the child: serve until the request pipe closes, never return into the parent's code
            status = 1
            try:
                for fd in (requests_write, replies_read, *_PARENT_ENDS):
                    with contextlib.suppress(OSError):
                        os.close(fd)
                _serve(job, requests_read, replies_write)
                status = 0
            finally:
                os._exit(status)
        os.close(requests_read)
        os.close(replies_write)
        self.pid = pid
        self._requests, self._replies = requests_write, replies_read
        self._pending = 0
        _PARENT_ENDS.update((requests_write, replies_read))
        self._finalizer = weakref.finalize(self, _stop, pid, requests_write, replies_read)

    @property
    def alive(self) -> bool:
        """Whether the worker takes requests (not closed, not found dead)."""
        return self._finalizer.alive

    def submit(self, data: bytes) -> bool:
        """Send a request; False when the worker is closed or dead (it is then closed)."""
        if not self.alive:
            return False
        try:
            _write(self._requests, _HEADER.pack(len(data)) + data)
        except OSError:
            self.close()
            return False
        self._pending += 1
        return True

    def result(self) -> Any:
        """The reply to the last request sent (the replies to earlier ones never asked for are skipped); None
        when the job failed, or the worker died (it is then closed) or has no request pending."""
        reply = None
        while self._pending and self.alive:
            header = _read(self._replies, _HEADER.size)
            body = _read(self._replies, _HEADER.unpack(header)[0]) if header is not None else None
            if body is None:
                self.close()
                return None
            self._pending -= 1
            reply = body
        if reply is None:
            return None
        try:
            return json.loads(reply)
        except ValueError:
            return None

    def close(self) -> None:
        """Stop the child (it finishes the job it is doing) and wait for it; idempotent."""
        self._finalizer()


def start_worker(job: Callable[[bytes], Any]) -> PassWorker | None:
    """A :class:`PassWorker` for ``job``, or None where ``os.fork`` is missing or fails, or when this process
    runs other threads."""
    if not hasattr(os, "fork") or (threading.active_count() > 1 and not FORK_WITH_THREADS):
        return None
    try:
        return PassWorker(job)
    except OSError:
        return None


def _serve(job: Callable[[bytes], Any], requests: int, replies: int) -> None:
    while True:
        header = _read(requests, _HEADER.size)
        data = _read(requests, _HEADER.unpack(header)[0]) if header is not None else None
        if data is None:
            return
        try:
            reply = json.dumps(job(data)).encode()
        except Exception:  # any failure of the job: the parent does it itself
            reply = b"null"
        _write(replies, _HEADER.pack(len(reply)) + reply)


def _read(fd: int, size: int) -> bytes | None:
    """Exactly ``size`` bytes, or None at the end of the pipe."""
    chunks: list[bytes] = []
    while size > 0:
        try:
            chunk = os.read(fd, min(size, 1 << 20))
        except OSError:
            return None
        if not chunk:
            return None
        chunks.append(chunk)
        size -= len(chunk)
    return b"".join(chunks)


def _write(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view) :]


def _stop(pid: int, requests: int, replies: int) -> None:
    """Close the parent's ends of a worker's pipes, then reap the child (killed after :data:`CLOSE_WAIT`)."""
    for fd in (requests, replies):
        _PARENT_ENDS.discard(fd)
        with contextlib.suppress(OSError):
            os.close(fd)
    deadline = time.monotonic() + CLOSE_WAIT
    try:
        while os.waitpid(pid, os.WNOHANG) == (0, 0):
            if time.monotonic() > deadline:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
                return
            time.sleep(0.002)
    except (ChildProcessError, ProcessLookupError):
        return
