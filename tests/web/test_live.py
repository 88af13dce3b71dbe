"""The web view attached to a real run: goals through the intake, the live snapshot."""

from __future__ import annotations

import time
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import httpx2
import pytest
from fastapi.testclient import TestClient

from knic.system import KnicSystem, build_system
from knic.web.app import create_app
from knic.web.audio import SpeechInput, decode_wav
from knic.web.live import LiveLink
from knic.web.view import JournalView
from knowledge_base import KnowledgeBase

VOICES = Path(__file__).resolve().parents[2] / "worlds" / "erl_home" / "voices" / "annie"


class Run:
    """A run with the web view attached; requests are answered while the test steps the bridge."""

    def __init__(self, system: KnicSystem, link: LiveLink, client: TestClient, journal: Path) -> None:
        self.system, self.link, self.client, self.journal = system, link, client, journal
        self._pool = ThreadPoolExecutor(1)

    def post(self, path: str, **kwargs: Any) -> httpx2.Response:
        future = self._pool.submit(self.client.post, path, **kwargs)
        while not future.done():  # the run loop's side: the bridge takes the goal on the run thread
            self.link.step(self.system.sim.time)
            time.sleep(0.002)
        return future.result()

    def journal_goals(self) -> dict[str, str]:
        """The goals as another process reads them from the journal: goal -> author."""
        reader = KnowledgeBase.from_journal(self.journal, read_only=True)
        try:
            return {str(g): p.source for g, p in reader.snapshot().goals.items()}
        finally:
            reader.close()


@pytest.fixture
def run(request: pytest.FixtureRequest, tmp_path: Path) -> Iterator[Run]:
    role = getattr(request, "param", "companion")
    journal = tmp_path / "run.sqlite"
    system = build_system(["(robot_at r2d2 kitchen)"], journal=journal, role=role, seed=0)
    link = LiveLink(system)
    app = create_app(
        lambda: JournalView(journal, world=system.world), live=link, speech=SpeechInput(link.vocabulary)
    )
    try:
        with TestClient(app) as client:
            yield Run(system, link, client, journal)
    finally:
        link.close()
        system.close()


def test_a_goal_from_the_page_goes_through_the_intake_into_the_kb(run: Run) -> None:
    reply = run.post("/api/goal", json={"text": "go to the bedroom"}).json()
    assert reply["outcome"] == "added" and reply["goals"] == ["(robot_at r2d2 bedroom)"]
    assert reply["reply"].startswith("You asked me to")
    assert run.journal_goals() == {"(robot_at r2d2 kitchen)": "user", "(robot_at r2d2 bedroom)": "web"}
    page_goals = {g["fact"]: g["author"] for g in run.client.get("/api/facts").json()["goals"]}
    assert page_goals["(robot_at r2d2 bedroom)"] == "web"
    refused = run.post("/api/goal", json={"text": "(robot_at r2d2 moon)"}).json()
    assert refused["outcome"] == "refused" and "moon" in refused["reason"]
    nonsense = run.post("/api/goal", json={"text": "sing me a song"}).json()
    assert nonsense["outcome"] == "refused"
    assert len(run.journal_goals()) == 2  # nothing added by either


def test_a_spoken_goal_is_recognised_in_memory(run: Run) -> None:
    wav = (VOICES / "request_02.wav").read_bytes()  # "bring me the remote"
    reply = run.post("/api/goal/audio", content=wav, headers={"content-type": "audio/wav"}).json()
    assert reply["heard"].startswith("bring me the remote") and reply["outcome"] == "added"
    assert reply["goals"] == ["(has annie remote)"]
    goals = run.journal_goals()
    assert goals and all(author in ("user", "speech") for author in goals.values())
    assert [g for g, a in goals.items() if a == "speech"] == reply["goals"]
    bad = run.post("/api/goal/audio", content=b"RIFF....WAVEjunk", headers={"content-type": "audio/wav"})
    assert bad.status_code == 422 and bad.json()["detail"].startswith("upload: not a PCM WAV file")


@pytest.mark.parametrize("run", ["service_semi_autonomous"], indirect=True)
def test_a_role_that_confirms_asks_first_and_the_answer_comes_from_the_box(run: Run) -> None:
    asked = run.post("/api/goal", json={"text": "go to the bedroom"}).json()
    assert asked["outcome"] == "asked" and asked["reply"].endswith("Is that right?")
    assert "(robot_at r2d2 bedroom)" not in run.journal_goals()
    run.link.take_snapshot(run.system.sim.time)
    assert run.client.get("/api/live").json()["intake"]["awaiting_answer"] == asked["reply"].removesuffix(
        " Is that right?"
    )
    added = run.post("/api/goal", json={"text": "yes"}).json()
    assert added["outcome"] == "added" and added["goals"] == ["(robot_at r2d2 bedroom)"]
    assert run.journal_goals()["(robot_at r2d2 bedroom)"] == "web"


def test_the_snapshot_shows_components_bus_tracks_and_ground_truth(run: Run) -> None:
    result = run.system.run(max_sim_time=30)
    assert result.success
    run.link.take_snapshot(run.system.sim.time)
    live = run.client.get("/api/live").json()
    components = {c["name"]: c for c in live["components"]}
    assert {"sim", "kgm2.cognition", "dispatcher", "web"} <= set(components)
    assert components["kp.robot_pose"]["rate"] == pytest.approx(10.0, rel=0.1)
    assert all(c["steps"] > 0 and c["max_ms"] >= c["mean_ms"] >= 0 for c in components.values())
    pose_topics = [t for t in live["bus"] if t["topic"].startswith("percept.pose")]
    stamps = [m["stamp"] for m in pose_topics[0]["messages"]]
    assert 1 < len(stamps) <= 5 and stamps == sorted(stamps) and stamps[-1] <= live["sim_time"]
    world = run.system.world
    truth = live["truth"]["robot"]
    assert world.rooms["kitchen"].contains(truth["x"], truth["y"])  # the goal holds in the ground truth
    believed = live["believed_pose"]
    assert abs(believed["x"] - truth["x"]) < 0.5 and abs(believed["y"] - truth["y"]) < 0.5
    seen = [t for t in live["tracks"] if t["voxels"]]
    assert seen and all(t["radius"] > 0 for t in seen)
    assert {d["name"] for d in live["devices"]} == set(world.devices)
    assert live["role"]["name"] == "companion"
    run.link.close()
    over = run.client.post("/api/goal", json={"text": "go to the bedroom"})
    assert over.status_code == 409 and over.json()["detail"] == "the run is over; it takes no more goals"


def test_decode_wav_reads_pcm_and_refuses_the_rest() -> None:
    import io
    import wave

    import numpy as np

    buf = io.BytesIO()
    with wave.open(buf, "wb") as w:
        w.setnchannels(2)
        w.setsampwidth(2)
        w.setframerate(8000)
        w.writeframes(np.full((8000, 2), 1000, dtype="<i2").tobytes())
    audio = decode_wav(buf.getvalue())
    assert audio.dtype == np.int16 and len(audio) == pytest.approx(16000, abs=2)  # 1 s at 16 kHz, mono
    for data, start in [(b"not audio", "upload: not a WAV file"), (b"RIFF\0\0\0\0WAVE", "upload: not a PCM")]:
        with pytest.raises(Exception, match=start):
            decode_wav(data)
