"""The n-gram recogniser's later member models decoded in forked worker processes
(:mod:`knic.language.passworker`): the same transcripts as in one process, a dead worker replaced by decoding
here, and no process left after ``close()`` or garbage collection; ``knic say`` runs only the first member's
phone loop in a child."""

from __future__ import annotations

import gc
import math
import os
import signal
import threading
import time
from pathlib import Path

import pytest

from knic.language import oneshot, passworker
from knic.language.lmspeech import NgramRecognizer
from knic.language.passworker import PassWorker, start_worker
from knic.language.vocabulary import Vocabulary
from knic.language.whisperpass import Heard

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
#: two espeak-ng commands, a flite voice (the wheel's model chosen) and another engine's other speech
UTTERANCES = [
    FIXTURES / "speech_people" / "dev" / "dev_001.wav",
    FIXTURES / "speech_people" / "dev" / "dev_006.wav",
    FIXTURES / "speech_engines_dev" / "engines_dev_001.wav",
]

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="workers need os.fork")


def _gone(pid: int) -> bool:
    """Whether the process no longer exists (reaped: not even a zombie child of this process)."""
    deadline = time.monotonic() + 5.0
    while time.monotonic() < deadline:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return True
        time.sleep(0.01)
    return False


def _heard(recognizer: NgramRecognizer) -> list[tuple[str, str, bool]]:
    """Transcripts of the utterances, twice (a pocketsphinx decoder scores its first utterance slightly
    differently from later ones, and the phone loop's scores depend on the utterances before)."""
    found = []
    for wav in UTTERANCES * 2:
        transcript = recognizer.recognize(wav)
        found.append((transcript.text, repr(transcript.score), transcript.in_grammar))
    return found


@pytest.fixture(autouse=True)
def _fork_even_beside_other_tests_threads(monkeypatch: pytest.MonkeyPatch) -> None:
    """Threads other tests left running must not turn the workers off here (that guard has its own test)."""
    monkeypatch.setattr(passworker, "FORK_WITH_THREADS", True)


@pytest.fixture(scope="module")
def sequential(vocabulary: Vocabulary) -> list[tuple[str, str, bool]]:
    """pocketsphinx's transcripts in this process alone (Whisper would settle some utterances without it)."""
    with NgramRecognizer(vocabulary, parallel=False, second_opinion=False) as recognizer:
        heard = _heard(recognizer)
        assert recognizer.worker_pids == ()
    return heard


def test_workers_hear_what_one_process_hears_and_leave_on_close(
    vocabulary: Vocabulary, sequential: list[tuple[str, str, bool]]
) -> None:
    recognizer = NgramRecognizer(vocabulary, second_opinion=False)
    assert recognizer.worker_pids == ()
    recognizer.recognize(UTTERANCES[0])
    pids: list[int] = list(recognizer.worker_pids)  # forked after the first utterance, decoded here
    assert len(pids) == 1
    pid = pids[0]
    recognizer.close()
    assert recognizer.worker_pids == () and _gone(pid)
    recognizer.recognize(UTTERANCES[0])  # still usable, in this process alone
    assert recognizer.worker_pids == ()
    with NgramRecognizer(vocabulary, second_opinion=False) as parallel:
        assert _heard(parallel) == sequential
        (pid,) = parallel.worker_pids
    assert _gone(pid)


def test_a_dead_worker_is_replaced_by_decoding_here(
    vocabulary: Vocabulary, sequential: list[tuple[str, str, bool]]
) -> None:
    recognizer = NgramRecognizer(vocabulary, second_opinion=False)
    heard = [recognizer.recognize(wav) for wav in UTTERANCES[:2]]
    (pid,) = recognizer.worker_pids
    os.kill(pid, signal.SIGKILL)
    heard += [recognizer.recognize(wav) for wav in [*UTTERANCES[2:], *UTTERANCES]]
    assert [(t.text, repr(t.score), t.in_grammar) for t in heard] == sequential
    assert recognizer.worker_pids == () and _gone(pid)


def test_garbage_collection_stops_the_workers(vocabulary: Vocabulary) -> None:
    recognizer = NgramRecognizer(vocabulary)
    recognizer.recognize(UTTERANCES[0], heard=lambda: Heard("", -5.0))  # Whisper unsure: pocketsphinx decodes
    (pid,) = recognizer.worker_pids
    whisper = recognizer.whisper_pid
    assert whisper is not None  # Whisper hears in a server process of its own from the start
    del recognizer
    gc.collect()
    assert _gone(pid) and _gone(whisper)


def test_the_whisper_server_leaves_on_close_and_is_replaced_when_dead(vocabulary: Vocabulary) -> None:
    with NgramRecognizer(vocabulary, parallel=False) as alive:
        expected = _heard(alive)
    assert any(math.isnan(float(score)) for _, score, _ in expected)  # Whisper settled some
    recognizer = NgramRecognizer(vocabulary, parallel=False)
    pid = recognizer.whisper_pid
    assert pid is not None
    os.kill(pid, signal.SIGKILL)  # a new server hears for it, with the same results
    assert _heard(recognizer) == expected
    assert recognizer.whisper_pid not in (None, pid) and _gone(pid)
    recognizer.close()
    with NgramRecognizer(vocabulary) as other:
        pid = other.whisper_pid
    assert pid is not None and _gone(pid) and other.whisper_pid is None


def test_a_worker_answers_each_request_and_none_when_its_job_fails() -> None:
    def job(data: bytes) -> object:
        if data == b"fail":
            raise ValueError(data)
        return [data.decode(), len(data)]

    worker = start_worker(job)
    assert isinstance(worker, PassWorker) and worker.alive
    big = "x" * 300_000  # larger than a pipe's buffer
    assert worker.submit(big.encode()) and worker.result() == [big, len(big)]
    assert worker.submit(b"fail") and worker.result() is None and worker.alive
    assert worker.submit(b"old") and worker.submit(b"new") and worker.result() == ["new", 3]
    assert worker.result() is None  # nothing pending
    worker.close()
    assert not worker.alive and not worker.submit(b"late") and _gone(worker.pid)
    worker.close()  # again: nothing happens


def test_say_runs_only_the_first_members_phone_loop_in_a_child() -> None:
    wav = str(UTTERANCES[0])
    passes = oneshot.start_passes(wav, [], "auto")
    try:
        score = passes.phone_score(0)
        assert isinstance(score, float) and score > 0.0
        assert passes.phone_score(1) is None  # the caller computes it when that member is chosen
    finally:
        passes.close()
    cancelled = oneshot.start_passes(wav, [], "auto")
    pids = cancelled.pids
    assert len(pids) == 4  # two n-gram passes, the first member's phone loop and Whisper
    cancelled.close()  # never asked: stopped
    assert all(_gone(pid) for pid in pids)


def test_a_process_with_other_threads_decodes_in_itself(monkeypatch: pytest.MonkeyPatch) -> None:
    """A fork could copy a lock another thread holds: no worker then, the caller decodes itself."""
    monkeypatch.setattr(passworker, "FORK_WITH_THREADS", False)
    stop = threading.Event()
    other = threading.Thread(target=stop.wait, daemon=True)
    other.start()
    try:
        assert start_worker(lambda data: len(data)) is None
    finally:
        stop.set()
        other.join()
