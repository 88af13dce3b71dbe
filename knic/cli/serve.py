"""``knic serve``: the robot's mind in a browser, from a run's journal (live while the run writes it).

The page shows the apartment map with where the robot believes things are, the fact table (status, author,
since, confidence; filter, search; click a fact for why), the plan and execution trace, and a time slider over
the journal. It follows a running ``knic run --journal FILE`` or shows a finished one; it never writes.
``knic run --serve`` serves the same page from inside the run, with the components, the bus, KGM-2's
octomaps, the ground truth and a goal box on top (see :func:`add_run_serve_arguments`).

Examples::

    knic serve --journal run.sqlite --trace run.jsonl            # http://127.0.0.1:8765/
    knic serve --journal run.sqlite --port 9000 --seconds 60
    knic run --goal "bring me my glasses" --serve --pace 2         # watch a run at twice real time

The web framework (FastAPI, uvicorn) is the optional extra ``web``: ``pip install 'knic[web]'``.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.util
import json
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import KnicError
from knic.cli.outputs import running_journal

if TYPE_CHECKING:
    from knic.system import KnicSystem


def _binding_arguments(parser: argparse.ArgumentParser, prefix: str = "") -> None:
    parser.add_argument(
        "--host",
        default="127.0.0.1",
        help=f"{prefix}address to serve on (default 127.0.0.1; others need --token)",
    )
    parser.add_argument(
        "--port", type=int, default=8765, help=f"{prefix}TCP port (default 8765; 0: any free port)"
    )
    parser.add_argument(
        "--token", help=f"{prefix}secret every API request must carry (Authorization: Bearer)"
    )


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--journal", required=True, type=Path, metavar="FILE", help="the SQLite journal of a run"
    )
    parser.add_argument("--trace", type=Path, metavar="FILE.jsonl", help="the run's trace (knic run --trace)")
    parser.add_argument(
        "--world",
        default="erl_home",
        help="world data for doors and devices (default erl_home; 'none': skip)",
    )
    _binding_arguments(parser)
    parser.add_argument("--seconds", type=float, metavar="N", help="stop after N seconds (default: until ^C)")
    parser.add_argument("--json", action="store_true", help='print {"url": ...} as JSON once serving')


def run(args: argparse.Namespace) -> int:
    from knic.web.server import check_binding
    from knowledge_base.journal import SqliteJournal

    check_binding(args.host, args.port, args.token)
    args.journal = running_journal(args.journal)
    SqliteJournal.read_meta(args.journal)  # a missing or foreign file is a one-line error here
    if args.seconds is not None and not args.seconds > 0:
        raise KnicError(f"--seconds: expected a positive number, got {args.seconds}")
    world = None
    if args.world != "none":
        from worlds.api import load_world

        world = load_world(args.world)
    server = _journal_server(args, world)
    server.start()
    try:
        if args.json:
            print(json.dumps({"url": server.url, "journal": str(args.journal)}), flush=True)
        else:
            print(f"knic: web view of {args.journal} at {server.url} (^C to stop)", flush=True)
        end = time.monotonic() + args.seconds if args.seconds is not None else None
        while end is None or time.monotonic() < end:
            time.sleep(0.2 if end is None else max(0.0, min(0.2, end - time.monotonic())))
    finally:
        server.stop()
    return 0


def _journal_server(args: argparse.Namespace, world: Any) -> Any:
    try:
        from knic.web.app import create_app
        from knic.web.server import LOOPBACK_HOSTS, WebServer, is_loopback
        from knic.web.view import JournalView, TraceFile
    except ModuleNotFoundError as exc:
        raise KnicError(
            f"knic serve needs the 'web' extra (pip install 'knic[web]'): {exc.name} is missing"
        ) from None
    from knic.bench.granny_annie.livescore import score_path

    journal = args.journal
    app = create_app(
        lambda: JournalView(journal, world=world),
        trace=TraceFile(args.trace) if args.trace is not None else None,
        score=score_path(journal),
        token=args.token,
        allowed_hosts=LOOPBACK_HOSTS if is_loopback(args.host) else None,
    )
    return WebServer(app, args.host, args.port)


# ---------------------------------------------------------------------- knic run --serve
def add_run_serve_arguments(parser: argparse.ArgumentParser) -> None:
    """The ``--serve`` options of ``knic run``."""
    parser.add_argument(
        "--serve", action="store_true", help="show the run live in a browser (needs the 'web' extra)"
    )
    _binding_arguments(parser, "with --serve: ")
    parser.add_argument(
        "--pace", type=float, metavar="X", help="with --serve: at most X simulated seconds per wall second"
    )
    parser.add_argument(
        "--linger",
        type=float,
        default=0.0,
        metavar="S",
        help="with --serve: keep the page up S s after the run; with --ros: keep the node up S s after it (a"
        " subscriber that joins then still gets the latched topics and the last 10,000 fact events)",
    )


def run_journal(args: argparse.Namespace) -> Path | None:
    """The journal the run writes: ``--journal``, or with ``--serve`` a new file in a temporary folder.

    Also checks the ``--serve`` options, before anything is built.

    Raises:
        KnicError: unsafe or invalid --serve options.
    """
    if getattr(args, "linger", 0.0) < 0:
        raise KnicError(f"--linger: expected seconds >= 0, got {args.linger}")
    if not getattr(args, "serve", False):
        return args.journal
    from knic.web.server import check_binding

    check_binding(args.host, args.port, args.token)
    if args.pace is not None and not args.pace > 0:
        raise KnicError(f"--pace: expected a positive number, got {args.pace}")
    missing = [name for name in ("fastapi", "uvicorn") if importlib.util.find_spec(name) is None]
    if missing:
        raise KnicError(f"--serve needs the 'web' extra (pip install 'knic[web]'): {missing[0]} is missing")
    if args.journal is not None:
        return args.journal
    path = Path(tempfile.mkdtemp(prefix="knic-run-")) / "journal.sqlite"
    print(f"knic: the run's journal is {path}", file=sys.stderr)
    return path


@contextlib.contextmanager
def serving(args: argparse.Namespace, system: KnicSystem, journal: Path | None) -> Iterator[None]:
    """With ``--serve``: the web view of ``system`` while the block runs (nothing otherwise)."""
    if not getattr(args, "serve", False) or journal is None:
        yield
        return
    from knic.web.server import ServeOptions, serve_run

    options = ServeOptions(args.host, args.port, args.token, args.pace, args.linger, args.speaker)
    with serve_run(options, system, journal=journal):
        yield
