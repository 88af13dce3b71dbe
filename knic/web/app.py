"""The web view's HTTP application (FastAPI): the page, its assets, the JSON API and the event stream.

The API (documented by OpenAPI at ``/docs``, schema at ``/openapi.json``):

* ``GET /api/info``: what is being shown (journal, run, whether goals are taken);
* ``GET /api/facts``: the fact table and the goals, now or at a past time (``at``), optionally filtered;
* ``GET /api/why?fact=(pred a b)``: why a fact is believed: provenance, support, history;
* ``GET /api/map``: the floor plan and where things are believed to be;
* ``GET /api/trace``: the plan and execution trace;
* ``GET /api/live``: the running system's snapshot (components, bus, tracks, ground truth);
* ``GET /api/score``: the Granny Annie referee's running score (a benchmark episode or a task scenario);
* ``POST /api/goal``: a command, PDDL goal or yes/no answer, through the goal intake;
* ``POST /api/goal/audio``: the same, spoken (a WAV file as the request body);
* ``GET /api/events``: server-sent events (see :mod:`knic.web.hub`).

Security: the server binds to loopback unless given a token (see :mod:`knic.web.server`); with a token,
every ``/api`` request must carry it (``Authorization: Bearer``, or ``?token=`` for the event stream). On
loopback the ``Host`` header must name loopback (no DNS rebinding). Request bodies are limited in size
(:data:`MAX_BODY`); goals enter only through the validated intake; no request names a file: the assets are
read from the package into memory when the app is made and looked up by fixed name.
"""

from __future__ import annotations

import asyncio
import contextlib
import math
import secrets
from collections.abc import AsyncIterator, Callable
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from fastapi import Depends, FastAPI, HTTPException, Query, Request, Response
from fastapi.concurrency import run_in_threadpool
from fastapi.openapi.docs import get_swagger_ui_html
from fastapi.responses import HTMLResponse, JSONResponse, StreamingResponse
from pydantic import BaseModel, Field
from starlette.middleware.trustedhost import TrustedHostMiddleware

from core.errors import KnicError
from knic import __version__
from knic.web.hub import Hub
from knic.web.limits import BodyLimit
from knic.web.view import BadQuery, JournalView, TraceSource

if TYPE_CHECKING:
    from knic.web.audio import SpeechInput
    from knic.web.live import LiveLink

#: largest request body per path (bytes); other paths take none
MAX_BODY = {"/api/goal": 4096, "/api/goal/audio": 2 * 1024 * 1024}
#: wall seconds a goal may wait for the run loop to take it
GOAL_TIMEOUT_S = 15.0
#: the page's own assets (package knic.web.assets), name -> media type
ASSETS = {"app.js": "text/javascript", "map.js": "text/javascript", "style.css": "text/css"}
#: what the page loads first (app.js ``load``), announced in the page so the browser asks at once
PRELOAD = ("/api/facts?compact=true", "/api/info", "/api/map", "/api/trace", "/api/live", "/api/score")
DOCS_ASSETS = {"swagger-ui-bundle.js": "text/javascript", "swagger-ui.css": "text/css"}
PAGE_HEADERS = {
    "Content-Security-Policy": "default-src 'self'; img-src 'self' data:; connect-src 'self'",
    "X-Content-Type-Options": "nosniff",
    "Cache-Control": "no-store",
}


class FactRecord(BaseModel):
    """One row of the fact table."""

    fact: str = Field(examples=["(object_at glasses kitchen)"])
    predicate: str
    arguments: list[str]
    status: Literal["given", "observed", "assumed", "effect"]
    author: str = Field(description="the component that wrote it (provenance source)")
    since: float = Field(description="clock time of the write that made it hold, seconds")
    confidence: float


class FactsResponse(BaseModel):
    """The fact base at one time."""

    seq: int = Field(description="the last journal event included")
    time: float | None
    at: float | None = Field(description="the time asked for (None: now)")
    facts: list[FactRecord] | None = Field(None, description="the facts (unless compact)")
    columns: list[str] | None = Field(None, description="compact: the columns of each row")
    rows: list[list[str | float]] | None = Field(None, description="compact: one row per fact")
    goals: list[FactRecord]


class WhyResponse(BaseModel):
    """Why a fact is (or is not) believed."""

    fact: str
    holds: bool
    goal: bool
    status: str | None = None
    author: str | None = None
    since: float | None = None
    confidence: float | None = None
    support: list[str] = Field(default_factory=list, description="ids of the knowledge units behind it")
    history: list[dict[str, Any]] = Field(description="every journal event about this fact, in order")


class GoalRequest(BaseModel):
    """A command in English, PDDL goals, or the answer to the robot's question."""

    text: str = Field(
        min_length=1, max_length=500, examples=["bring me my glasses", "(robot_at r2d2 kitchen)"]
    )


class GoalReply(BaseModel):
    """What the goal intake made of it."""

    outcome: Literal["added", "asked", "refused", "declined", "asked_again"]
    goals: list[str]
    reply: str = Field(description="what the robot said")
    reason: str = Field(description="why, for refused and declined")
    heard: str | None = Field(default=None, description="the recognised words (spoken goals)")


def _load(package: str, names: dict[str, str], folder: str = "") -> dict[str, tuple[bytes, str]]:
    """Read a package's assets into memory: name -> (bytes, media type)."""
    root = resources.files(package)
    if folder:
        root = root.joinpath(folder)
    return {name: (root.joinpath(name).read_bytes(), media) for name, media in names.items()}


def create_app(
    open_view: Callable[[], JournalView],
    *,
    live: LiveLink | None = None,
    trace: TraceSource | None = None,
    speech: SpeechInput | None = None,
    token: str | None = None,
    allowed_hosts: list[str] | None = None,
    poll_s: float = 0.05,
    score: Path | None = None,
) -> FastAPI:
    """The web view's application.

    Args:
        open_view: opens the journal view (called once, on the server's event-loop thread).
        live: the running system (``knic run --serve``); None follows files only (goals are refused).
        trace: the trace file to follow when there is no running system.
        speech: recognises uploaded WAV goals (None: uploads are refused).
        token: the secret every ``/api`` request must carry, or None (loopback only).
        allowed_hosts: the ``Host`` header values accepted (None: any).
        poll_s: wall seconds between two polls of the journal.
        score: the run's score file (:func:`knic.bench.granny_annie.livescore.score_path` of the journal).
    """
    hub = Hub(open_view, live=live, trace=trace, poll_s=poll_s, score=score)
    assets = _load("knic.web.assets", ASSETS)
    index = resources.files("knic.web.assets").joinpath("index.html").read_bytes()
    if token is None:  # the page's first requests start while it loads (with a token the page adds it)
        links = "".join(f'<link rel="preload" href="{u}" as="fetch" crossorigin>\n' for u in PRELOAD)
        index = index.replace(b"<!--preload-->\n", links.encode())
    docs_assets: dict[str, tuple[bytes, str]] = {}

    @contextlib.asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        await hub.start()
        try:
            yield
        finally:
            await hub.stop()

    app = FastAPI(
        title="KnIC web view",
        version=__version__,
        description="The robot's mind, live: facts, why, map, plan and trace, components, goals.",
        docs_url=None,
        redoc_url=None,
        lifespan=lifespan,
    )
    app.state.hub = hub
    app.add_middleware(BodyLimit, limits=MAX_BODY)
    if allowed_hosts is not None:
        app.add_middleware(TrustedHostMiddleware, allowed_hosts=allowed_hosts)

    def authorise(request: Request) -> None:
        if token is None:
            return
        given = request.headers.get("authorization", "").removeprefix("Bearer ").strip()
        given = given or request.query_params.get("token", "")
        if not secrets.compare_digest(given.encode(), token.encode()):
            raise HTTPException(401, "missing or wrong token (Authorization: Bearer TOKEN, or ?token=)")

    guarded = [Depends(authorise)]

    def sync() -> None:
        """Read what the writer appended (and stream it to the pages) so an answer is never behind."""
        try:
            hub.poll_once()
        except KnicError as exc:
            raise HTTPException(503, f"journal: {exc}") from None

    def parse_at(at: float | None) -> float | None:
        if at is not None and not math.isfinite(at):
            raise HTTPException(400, f"at: expected a finite time in seconds, got {at}")
        return at

    # ------------------------------------------------------------------ page and assets
    @app.get("/", include_in_schema=False)
    async def page() -> Response:
        return Response(index, media_type="text/html; charset=utf-8", headers=PAGE_HEADERS)

    @app.get("/favicon.ico", include_in_schema=False)
    async def favicon() -> Response:
        return Response(status_code=204)

    @app.get("/assets/{name}", include_in_schema=False)
    async def asset(name: str) -> Response:
        found = assets.get(name)
        if found is None:
            raise HTTPException(404, "no such asset")
        return Response(found[0], media_type=found[1], headers=PAGE_HEADERS)

    @app.get("/docs", include_in_schema=False)
    async def docs() -> HTMLResponse:
        return get_swagger_ui_html(
            openapi_url="/openapi.json",
            title="KnIC web view API",
            swagger_js_url="/docs-assets/swagger-ui-bundle.js",
            swagger_css_url="/docs-assets/swagger-ui.css",
            swagger_favicon_url="data:,",
        )

    @app.get("/docs-assets/{name}", include_in_schema=False)
    async def docs_asset(name: str) -> Response:
        if name not in DOCS_ASSETS:
            raise HTTPException(404, "no such asset")
        if not docs_assets:  # swagger-ui ships in the fastapi-offline package (no CDN)
            docs_assets.update(_load("fastapi_offline", DOCS_ASSETS, "static"))
        body, media = docs_assets[name]
        return Response(body, media_type=media, headers={"Cache-Control": "max-age=3600"})

    # ------------------------------------------------------------------ API
    @app.get("/api/info", dependencies=guarded, tags=["view"])
    async def info() -> dict[str, Any]:
        """What the page shows: the journal's span, whether a run is attached and takes goals."""
        sync()
        return {
            "version": __version__,
            "mode": "run" if live is not None else "journal",
            "timeline": hub.view.timeline(),
            "goals": live is not None and not live.closed,
            "speech": speech is not None and live is not None and not live.closed,
            "trace": hub.trace is not None,
            "world": hub.view.world.name if hub.view.world is not None else None,
        }

    @app.get("/api/facts", dependencies=guarded, tags=["facts"], responses={200: {"model": FactsResponse}})
    async def facts(
        at: float | None = Query(None, description="clock time in seconds (default: now)"),
        predicate: str | None = Query(None, max_length=100),
        status: Literal["given", "observed", "assumed", "effect"] | None = None,
        author: str | None = Query(None, max_length=100),
        q: str | None = Query(None, max_length=200, description="text the fact contains"),
        compact: bool = Query(False, description='"rows" of [fact, status, author, since, confidence]'),
    ) -> Response:
        """The fact table (with status, author, since, confidence) and the goals."""
        sync()
        if compact and at is None and not (predicate or status or author or q):
            return Response(hub.whole_facts(), media_type="application/json")  # the page's load
        try:
            body = hub.view.facts(
                parse_at(at), predicate=predicate, status=status, author=author, text=q, compact=compact
            )
        except BadQuery as exc:
            raise HTTPException(400, str(exc)) from None
        return JSONResponse(body)

    @app.get("/api/why", dependencies=guarded, tags=["facts"], response_model=WhyResponse)
    async def why(
        fact: str = Query(..., max_length=400, examples=["(robot_at r2d2 kitchen)"]),
        at: float | None = Query(None, description="clock time in seconds (default: now)"),
    ) -> dict[str, Any]:
        """Why a fact is believed: who wrote it, when, on what support, and its whole history."""
        sync()
        try:
            return hub.view.why(fact, parse_at(at))
        except BadQuery as exc:
            raise HTTPException(400, str(exc)) from None

    @app.get("/api/map", dependencies=guarded, tags=["view"])
    async def map_(at: float | None = Query(None, description="clock time in seconds")) -> JSONResponse:
        """Rooms, doors, furniture, devices, and where the robot, items and people are believed to be."""
        sync()
        return JSONResponse(hub.view.map(parse_at(at)))

    @app.get("/api/trace", dependencies=guarded, tags=["plan"])
    async def trace_(after: int = Query(0, ge=0)) -> dict[str, Any]:
        """The plan and execution trace: plans, dispatches, outcomes, replans, goals (after the first n)."""
        sync()
        if hub.trace is None:
            return {"after": after, "count": 0, "events": []}
        events = hub.trace.events(after)[: max(0, hub.trace_count - after)]
        return {"after": after, "count": hub.trace_count, "events": events}

    @app.get("/api/live", dependencies=guarded, tags=["run"])
    async def live_() -> JSONResponse:
        """The running system: components, bus, tracks with voxels, path, ground truth, role, devices."""
        if live is None:
            return JSONResponse({"state": "none"})
        return JSONResponse(live.snapshot)

    @app.get("/api/score", dependencies=guarded, tags=["run"])
    async def score_() -> JSONResponse:
        """The Granny Annie referee's score so far (judged from ground truth only): achievements per kind,
        penalties, disqualifications, and ``final`` once the run ended; ``{"state": "none"}`` without one."""
        sync()
        return JSONResponse(hub.score if hub.score is not None else {"state": "none"})

    async def submit(text: str, source: str) -> dict[str, Any]:
        if live is None:
            raise HTTPException(
                409, "this page follows a journal; goals go to a run started with knic run --serve"
            )
        from knic.web.live import LinkClosed

        future = live.submit(text, source=source)
        try:
            return await asyncio.wait_for(asyncio.wrap_future(future), GOAL_TIMEOUT_S)
        except LinkClosed as exc:
            raise HTTPException(409, str(exc)) from None
        except TimeoutError:
            raise HTTPException(503, f"the run did not take the goal within {GOAL_TIMEOUT_S:g} s") from None

    @app.post("/api/goal", dependencies=guarded, tags=["run"], response_model=GoalReply)
    async def goal(request: GoalRequest) -> dict[str, Any]:
        """Give the robot a command, PDDL goals or a yes/no answer; all go through the goal intake."""
        return await submit(request.text, "web")

    @app.post(
        "/api/goal/audio",
        dependencies=guarded,
        tags=["run"],
        response_model=GoalReply,
        openapi_extra={
            "requestBody": {"content": {"audio/wav": {"schema": {"type": "string", "format": "binary"}}}}
        },
    )
    async def goal_audio(request: Request) -> dict[str, Any]:
        """A spoken command or answer: a PCM WAV file (at most 2 MiB, 30 s) as the request body."""
        if live is None or speech is None:
            raise HTTPException(
                409, "this page takes spoken goals only from a run started with knic run --serve"
            )
        data = await request.body()
        answering = live.intake.awaiting_answer is not None
        try:
            heard = await run_in_threadpool(speech.transcribe, data, answer=answering)
        except KnicError as exc:
            raise HTTPException(422, str(exc)) from None
        reply = await submit(heard, "speech")
        return {**reply, "heard": heard}

    @app.get("/api/events", dependencies=guarded, tags=["view"], response_class=StreamingResponse)
    async def events(
        request: Request,
        after: int = Query(0, ge=0, description="the last journal event the page has"),
        trace_after: int = Query(0, ge=0, description="trace events the page has"),
    ) -> StreamingResponse:
        """Server-sent events: ``changes`` (journal), ``trace``, ``live`` (snapshot), ``reset``."""
        last = request.headers.get("last-event-id", "")
        if last.isdigit():
            after = max(after, int(last))
        return StreamingResponse(
            hub.stream(after, trace_after),
            media_type="text/event-stream",
            headers={"Cache-Control": "no-store", "X-Accel-Buffering": "no"},
        )

    return app
