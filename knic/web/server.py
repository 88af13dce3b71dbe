"""Serving the web view: uvicorn on a thread of its own, bound to loopback unless a token guards it.

:class:`WebServer` binds its socket at construction (a taken port is a one-line error before anything
runs), serves on a daemon thread with its own event loop, and stops on :meth:`WebServer.stop`.
:func:`serve_run` attaches the view to a running system (``knic run --serve``).
"""

from __future__ import annotations

import contextlib
import ipaddress
import socket
import sys
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from core.errors import KnicError

if TYPE_CHECKING:
    from fastapi import FastAPI

    from knic.system import KnicSystem

#: Host header values accepted when bound to loopback (a page on another name is refused: DNS rebinding)
LOOPBACK_HOSTS = ["127.0.0.1", "localhost", "::1"]
MIN_TOKEN = 16


def is_loopback(host: str) -> bool:
    """Whether ``host`` is a loopback name or address (``localhost``, ``127.0.0.0/8``, ``::1``)."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def check_binding(host: str, port: int, token: str | None) -> None:
    """Refuse what is unsafe or impossible before anything is built.

    Raises:
        KnicError: a non-loopback address without a token, a short token, or a port out of range.
    """
    if not 0 <= port <= 65535:
        raise KnicError(f"--port: expected 0..65535, got {port}")
    if token is not None and len(token) < MIN_TOKEN:
        raise KnicError(f"--token: use at least {MIN_TOKEN} characters")
    if not is_loopback(host) and token is None:
        raise KnicError(
            f"--host {host}: serving beyond loopback needs --token (every API request must carry it)"
        )


class WebServer:
    """uvicorn serving ``app`` on ``host:port`` from a background thread.

    Args:
        app: the ASGI application (:func:`knic.web.app.create_app`).
        host: address to bind (loopback by default; see :func:`check_binding`).
        port: TCP port; 0 picks a free one (see :attr:`url`).

    Raises:
        KnicError: the address cannot be bound (in use, not local).
    """

    def __init__(self, app: FastAPI, host: str = "127.0.0.1", port: int = 8765) -> None:
        import uvicorn

        family = socket.AF_INET6 if ":" in host else socket.AF_INET
        self._sock = socket.socket(family, socket.SOCK_STREAM)
        self._sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            self._sock.bind((host, port))
        except OSError as exc:
            self._sock.close()
            raise KnicError(f"cannot serve on {host}:{port}: {exc.strerror or exc}") from None
        self.host = host
        self.port = self._sock.getsockname()[1]
        config = uvicorn.Config(
            app,
            log_level="warning",
            http="h11",
            ws="none",
            lifespan="on",
            limit_concurrency=64,
            timeout_graceful_shutdown=1,
            h11_max_incomplete_event_size=16 * 1024,
            server_header=False,
        )
        self._server = uvicorn.Server(config)
        self._thread = threading.Thread(target=self._run, name="knic-web", daemon=True)
        self._error: BaseException | None = None

    @property
    def url(self) -> str:
        """The page's address."""
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"http://{host}:{self.port}/"

    def _run(self) -> None:
        try:
            self._server.run(sockets=[self._sock])
        except BaseException as exc:  # reported by start() / stop()
            self._error = exc

    def start(self, timeout: float = 20.0) -> WebServer:
        """Start serving; returns once the server accepts requests.

        Raises:
            KnicError: the server did not start (its reason).
        """
        self._thread.start()
        deadline = time.monotonic() + timeout
        while not self._server.started:
            if not self._thread.is_alive() or time.monotonic() > deadline:
                self.stop()
                raise KnicError(f"web view did not start: {self._error or 'timed out'}")
            time.sleep(0.01)
        return self

    def stop(self) -> None:
        """Stop serving and wait for the thread (idempotent)."""
        self._server.should_exit = True
        if self._thread.is_alive():
            self._thread.join(timeout=10)
        self._sock.close()


@dataclass
class ServeOptions:
    """How ``knic run --serve`` serves its page (checked before the run is built)."""

    host: str = "127.0.0.1"
    port: int = 8765
    token: str | None = None
    pace: float | None = None
    linger: float = 0.0
    speaker: str = "annie"


@contextlib.contextmanager
def serve_run(options: ServeOptions, system: KnicSystem, *, journal: Path) -> Iterator[WebServer]:
    """Serve the web view of ``system`` while the block runs (``knic run --serve``).

    The page follows ``journal`` (the run's journal file) and the run's live link (goals, components, bus,
    tracks, ground truth). After the block, the page stays up ``options.linger`` seconds (goals are then
    refused: the run is over).
    """
    from knic.bench.granny_annie.livescore import score_path
    from knic.web.app import create_app
    from knic.web.audio import SpeechInput
    from knic.web.live import LiveLink
    from knic.web.view import JournalView

    check_binding(options.host, options.port, options.token)
    link = LiveLink(system, pace=options.pace, speaker=options.speaker)
    world = system.world
    app = create_app(
        lambda: JournalView(journal, world=world),
        live=link,
        speech=SpeechInput(link.vocabulary),
        score=score_path(journal),
        token=options.token,
        allowed_hosts=LOOPBACK_HOSTS if is_loopback(options.host) else None,
    )
    server = WebServer(app, options.host, options.port).start()
    print(f"knic: web view at {server.url}", file=sys.stderr, flush=True)
    interrupted = False
    try:
        yield server
    except KeyboardInterrupt:
        interrupted = True
        raise
    finally:
        link.close()
        if options.linger > 0 and not interrupted:
            print(
                f"knic: run over; the page stays up {options.linger:g} s (^C to stop)",
                file=sys.stderr,
                flush=True,
            )
            with contextlib.suppress(KeyboardInterrupt):
                time.sleep(options.linger)
        server.stop()
