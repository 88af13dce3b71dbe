"""The JSON API over a journal a real knowledge base writes (FastAPI's test client; no browser)."""

from __future__ import annotations

import asyncio
import json
from collections.abc import Iterator
from types import SimpleNamespace
from typing import Any, cast

import pytest
from fastapi.testclient import TestClient

from knic.bench.granny_annie.livescore import LiveScore, score_path
from knic.bench.granny_annie.recording import Recorder
from knic.bench.granny_annie.referee import Sample, Timeline
from knic.web.app import create_app
from knic.web.hub import Hub
from knic.web.limits import BodyLimit
from knic.web.view import JournalView, TraceFile
from knowledge_base import BeliefStatus
from planner.trace import EventKind, Trace, TraceEvent
from tests.bench.test_granny_annie_referee import START, changed, episode, moving
from tests.web.conftest import Writer
from worlds.model import World

TOKEN = "a-token-of-sixteen-chars"


@pytest.fixture
def client(writer: Writer, world: World) -> Iterator[TestClient]:
    app = create_app(lambda: JournalView(writer.journal, world=world), trace=TraceFile(writer.trace))
    with TestClient(app) as c:
        yield c


def test_facts_carry_status_author_since_and_confidence(writer: Writer, client: TestClient) -> None:
    writer.at(12.5).add_fact(
        "object_at",
        "glasses",
        "kitchen",
        source="kp'.object_at",
        status=BeliefStatus.OBSERVED,
        confidence=0.8,
    )
    body = client.get("/api/facts", params={"predicate": "object_at"}).json()
    assert body["facts"] == [
        {
            "fact": "(object_at glasses kitchen)",
            "predicate": "object_at",
            "arguments": ["glasses", "kitchen"],
            "status": "observed",
            "author": "kp'.object_at",
            "since": 12.5,
            "confidence": 0.8,
        }
    ]
    everything = client.get("/api/facts").json()
    assert everything["seq"] == writer.kb.journal.last_seq
    assert len(everything["facts"]) == len(writer.kb.snapshot().facts)
    assert client.get("/api/facts", params={"status": "assumed", "q": "glasses"}).json()["facts"]
    compact = client.get("/api/facts", params={"compact": True, "predicate": "object_at"}).json()
    assert compact["columns"] == ["fact", "status", "author", "since", "confidence"]
    assert compact["rows"] == [["(object_at glasses kitchen)", "observed", "kp'.object_at", 12.5, 0.8]]
    bad = client.get("/api/facts", params={"predicate": "object_at_x"})
    assert bad.status_code == 400
    assert bad.json()["detail"] == "predicate: unknown predicate 'object_at_x' in domain erl_home"


def test_why_gives_provenance_support_and_history(writer: Writer, client: TestClient) -> None:
    kb = writer.at(3.0)
    kb.add_fact("person_at", "annie", "bedroom", source="kp'.person_at", support=("cku:1", "llku:2"))
    writer.at(9.0).remove_fact("person_at", "annie", "bedroom", source="kp'.person_at")
    writer.at(11.0).add_fact("person_at", "annie", "kitchen", source="kp'.person_at")
    gone = client.get("/api/why", params={"fact": "(person_at annie bedroom)"}).json()
    assert gone["holds"] is False
    assert [(c["kind"], c["time"]) for c in gone["history"]] == [("add_fact", 3.0), ("remove_fact", 9.0)]
    then = client.get("/api/why", params={"fact": "(person_at annie bedroom)", "at": 5.0}).json()
    assert then["holds"] is True
    assert (then["author"], then["since"], then["support"]) == ("kp'.person_at", 3.0, ["cku:1", "llku:2"])
    assert [c["kind"] for c in then["history"]] == ["add_fact"]
    for fact, detail in [
        (
            "(person_at annie moon)",
            "fact (person_at annie moon): 'moon' is not an instance known to this journal",
        ),
        ("(person_at annie)", "fact (person_at annie): person_at takes 2 argument(s), got 1"),
        (
            "person_at annie",
            "fact: cannot parse fact 'person_at annie': expected a ground atom like '(pred arg1 arg2)'",
        ),
    ]:
        response = client.get("/api/why", params={"fact": fact})
        assert (response.status_code, response.json()["detail"]) == (400, detail)


def test_facts_at_a_past_time(writer: Writer, client: TestClient) -> None:
    writer.at(4.0).add_fact("object_at", "remote", "living_room", source="kp'.object_at")
    writer.at(8.0).remove_fact("object_at", "remote", "living_room", source="kp'.object_at")
    facts = lambda **p: {f["fact"] for f in client.get("/api/facts", params=p).json()["facts"]}  # noqa: E731
    assert "(object_at remote living_room)" in facts(at=5.0)
    assert "(object_at remote living_room)" not in facts(at=9.0)
    assert "(object_at remote living_room)" not in facts()
    assert client.get("/api/facts", params={"at": "nan"}).status_code == 400


def test_map_draws_the_world_and_places_beliefs(writer: Writer, client: TestClient, world: World) -> None:
    kb = writer.at(2.0)
    kb.add_fact("object_at", "glasses", "bedroom", source="kp'.object_at", status=BeliefStatus.OBSERVED)
    kb.set_anchor(
        "glasses", {"pose": {"position": [1.5, 6.0, 0.8]}, "frame": "world"}, source="kp'.object_at"
    )
    kb.add_fact("person_at", "annie", "kitchen", source="kp'.person_at", status=BeliefStatus.OBSERVED)
    body = client.get("/api/map").json()
    assert {r["name"] for r in body["rooms"]} == set(world.rooms)
    assert {f["name"] for f in body["furniture"]} == set(world.furniture)
    assert len(body["doors"]) == len(world.doors) and body["note"] == ""
    believed = body["believed"]
    glasses = next(e for e in believed["items"] if e["name"] == "glasses")
    assert (glasses["x"], glasses["y"], glasses["how"]) == (1.5, 6.0, "anchor")
    annie = next(e for e in believed["people"] if e["name"] == "annie")
    assert annie["fact"] == "(person_at annie kitchen)" and world.rooms["kitchen"].contains(
        annie["x"], annie["y"]
    )
    robot = believed["robot"][0]
    assert robot["name"] == world.robot.name and robot["status"] == "given"
    assert any(c["fact"].startswith("(possibly_at") for c in believed["candidates"])


def test_trace_follows_the_trace_file(writer: Writer, client: TestClient) -> None:
    assert client.get("/api/trace").json()["events"] == []
    with writer.trace.open("w", encoding="utf-8") as stream:
        trace = Trace(stream)
        trace.emit(TraceEvent(EventKind.PLAN, 0.0, plan=("(move r2d2 entrance_hall hallway)",)))
        trace.emit(TraceEvent(EventKind.DISPATCH, 0.1, action="(move r2d2 entrance_hall hallway)"))
        stream.write('{"kind": "succ')  # a line being written is not read yet
        stream.flush()
        body = client.get("/api/trace").json()
    assert [e["kind"] for e in body["events"]] == ["plan", "dispatch"]
    assert body["events"][0]["plan"] == ["(move r2d2 entrance_hall hallway)"]
    assert client.get("/api/trace", params={"after": 1}).json()["events"][0]["kind"] == "dispatch"


def test_goals_need_a_running_system(client: TestClient) -> None:
    response = client.post("/api/goal", json={"text": "bring me my glasses"})
    assert response.status_code == 409
    assert "follows a journal" in response.json()["detail"]
    assert client.post("/api/goal", json={"text": ""}).status_code == 422
    assert client.get("/api/info").json()["goals"] is False


def test_request_size_is_limited(client: TestClient) -> None:
    big = client.post(
        "/api/goal", content=b'{"text": "' + b"a" * 5000 + b'"}', headers={"content-type": "application/json"}
    )
    assert big.status_code == 413
    assert big.json()["detail"] == "request body too large: at most 4096 bytes here"
    assert client.post("/api/facts", content=b"x").status_code == 413  # paths that take no body take none


def test_a_body_without_declared_length_is_cut_off_at_the_limit() -> None:
    read: list[int] = []

    async def upload(scope: Any, receive: Any, send: Any) -> None:  # reads the whole body, answers its size
        size, more = 0, True
        while more:
            message = await receive()
            size += len(message.get("body", b""))
            more = message.get("more_body", False)
        read.append(size)
        await send({"type": "http.response.start", "status": 200, "headers": []})
        await send({"type": "http.response.body", "body": str(size).encode()})

    c = TestClient(BodyLimit(upload, {"/up": 10_000}))  # no lifespan: a bare ASGI app
    assert c.post("/up", content=iter([b"x" * 1000] * 5)).text == "5000"
    chunked = c.post("/up", content=iter([b"x" * 1000] * 50))
    assert chunked.status_code == 413
    assert chunked.json()["detail"] == "request body too large: at most 10000 bytes here"
    assert read == [5000]  # the oversized body never reached the application whole


def test_assets_are_fixed_names_and_the_page_is_self_contained(client: TestClient) -> None:
    page = client.get("/")
    assert page.status_code == 200 and "default-src 'self'" in page.headers["content-security-policy"]
    for src in ("/assets/app.js", "/assets/map.js", "/assets/style.css"):
        assert src in page.text and client.get(src).status_code == 200
    assert "http" not in page.text.replace("http-equiv", "")  # nothing loaded from elsewhere
    for bad in (
        "/assets/..%2F__init__.py",
        "/assets/index.html",
        "/assets/%2Fetc%2Fpasswd",
        "/docs-assets/x.js",
    ):
        assert client.get(bad).status_code == 404


def test_openapi_documents_the_api_offline(client: TestClient) -> None:
    docs = client.get("/docs")
    assert docs.status_code == 200 and "/docs-assets/swagger-ui-bundle.js" in docs.text
    assert "cdn" not in docs.text.lower()
    assert client.get("/docs-assets/swagger-ui-bundle.js").status_code == 200
    paths = client.get("/openapi.json").json()["paths"]
    for path in ("/api/facts", "/api/why", "/api/trace", "/api/map", "/api/goal", "/api/events"):
        assert path in paths
    for path in ("/api/live", "/api/score"):
        assert path in paths
    assert "post" in paths["/api/goal"]


def test_token_and_host_guard_the_api(writer: Writer, world: World) -> None:
    app = create_app(
        lambda: JournalView(writer.journal, world=world),
        token=TOKEN,
        allowed_hosts=["127.0.0.1", "testserver"],
    )
    with TestClient(app) as c:
        assert c.get("/api/facts").status_code == 401
        assert (
            c.get("/api/facts", headers={"Authorization": "Bearer wrong-token-wrong-token"}).status_code
            == 401
        )
        assert c.get("/api/facts", headers={"Authorization": f"Bearer {TOKEN}"}).status_code == 200
        assert c.get("/api/info", params={"token": TOKEN}).status_code == 200
        assert (
            c.get("/api/info", params={"token": TOKEN}, headers={"Host": "evil.example"}).status_code == 400
        )
        assert c.get("/").status_code == 200  # the page itself holds no data


def test_event_stream_sends_the_backlog_then_each_journal_write(writer: Writer, world: World) -> None:
    """The hub's stream as a page reads it: events after the page's seq, then the writes as they come."""

    async def scenario() -> list[tuple[str, dict[str, Any]]]:
        hub = Hub(lambda: JournalView(writer.journal, world=world), poll_s=3600)
        await hub.start()
        seq = hub.view.seq
        writer.at(1.0).add_fact("object_at", "tablet", "bedroom", source="kp'.object_at")
        stream = hub.stream(seq, 0)
        got = [await anext(stream), await anext(stream)]  # hello, then the backlog
        writer.at(2.0).add_fact("object_at", "mug", "kitchen", source="kp'.object_at")
        hub.poll_once()
        got.append(await anext(stream))
        await hub.stop()
        rest = [m async for m in stream]
        assert rest == []  # stop ends every stream
        return [_parse(m) for m in got]

    (hello, _first), (changes1, data1), (changes2, data2) = asyncio.run(scenario())
    assert hello == "hello" and changes1 == changes2 == "changes"
    assert [c["fact"] for c in data1["changes"]] == ["(object_at tablet bedroom)"]
    assert [(c["fact"], c["author"]) for c in data2["changes"]] == [
        ("(object_at mug kitchen)", "kp'.object_at")
    ]
    assert data2["seq"] == writer.kb.journal.last_seq


def test_the_referees_score_file_is_served_and_streamed(writer: Writer, world: World) -> None:
    """``knic serve --journal`` of a benchmark episode: the score file beside the journal (written by the
    referee's :class:`LiveScore`) reaches /api/score and the event stream each time it changes."""
    path = score_path(writer.journal)
    start = frozenset(START)
    timeline = Timeline(samples=moving(start, 0.0, 5.0))
    live = LiveScore(cast(Recorder, SimpleNamespace(timeline=timeline)), episode(), lambda: None, path)

    async def scenario() -> tuple[list[tuple[str, dict[str, Any]]], dict[str, Any]]:
        hub = Hub(lambda: JournalView(writer.journal, world=world), poll_s=3600, score=path)
        await hub.start()
        hub.poll_once()
        assert hub.score is None  # no score file yet
        live.judge(5.0)
        stream = hub.stream(hub.view.seq, 0)
        got = [await anext(stream), await anext(stream)]  # hello, then the score as the backlog
        visit = changed(set(START), (("robot_at", "r2d2", "entrance_hall"), ("robot_at", "r2d2", "bedroom")))
        timeline.samples.append(Sample(5.5, visit, (3.0, 0.0, 0.0)))
        live.judge(6.0)
        hub.poll_once()
        got.append(await anext(stream))
        await hub.stop()
        return [_parse(m) for m in got], dict(hub.score or {})

    messages, last = asyncio.run(scenario())
    assert [kind for kind, _ in messages] == ["hello", "score", "score"]
    assert messages[1][1]["score"]["achievements"] == 0
    assert messages[2][1]["score"]["achieved"]["entered_room"] == 1
    assert last == json.loads(path.read_text())
    app = create_app(lambda: JournalView(writer.journal, world=world), score=path)
    with TestClient(app) as c:
        assert c.get("/api/score").json() == last
    with TestClient(create_app(lambda: JournalView(writer.journal, world=world))) as c:
        assert c.get("/api/score").json() == {"state": "none"}


def _parse(message: str) -> tuple[str, dict[str, Any]]:
    fields = dict(line.split(": ", 1) for line in message.strip().splitlines() if not line.startswith(":"))
    return fields["event"], json.loads(fields["data"])
