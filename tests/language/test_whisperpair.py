"""Whisper's server with a partner for the stretched hearings (knic.language.whisperpair): the paces split
between two processes give the transcripts one server gives, a partner that died is made up for, and the
server keeps an utterance it is not asked to hear."""

from __future__ import annotations

import os
import signal
from pathlib import Path

import pytest

from knic.language.audio import pcm_bytes
from knic.language.judging import STRETCH
from knic.language.whisperpair import PairedServer
from knic.language.whisperpass import BEAM, WhisperServer, world_prompt

#: "put the blinds at 75 percent" in a voice no acoustic adaptation heard
BLINDS = Path(__file__).resolve().parents[1] / "fixtures" / "speech_people3" / "dev" / "people3_068.wav"


def _stretched(server: WhisperServer, samples: bytes) -> list[list[object]]:
    assert server.hear(samples) is not None
    assert server.ask(samples, {"stretch": list(STRETCH)})
    found = server.answer()
    assert isinstance(found, list)
    return found


@pytest.fixture(scope="module")
def alone(vocabulary):
    """What one server hears at the other paces, in one batch."""
    server = WhisperServer(world_prompt(vocabulary))
    try:
        return _stretched(server, pcm_bytes(BLINDS))
    finally:
        server.close()


def test_the_paces_split_between_two_servers_are_heard_as_by_one(vocabulary, alone):
    samples = pcm_bytes(BLINDS)
    server = PairedServer(world_prompt(vocabulary))
    try:
        first = _stretched(server, samples)  # heard by the server alone; its partner starts meanwhile
        partner = server._partner
        assert partner is not None and partner.pid not in (None, server.pid)
        split = _stretched(server, samples)
        assert len(first) == len(split) == len(STRETCH) * BEAM
        # the same transcripts, pace after pace (the scores may differ in the last digits: a batch of one)
        assert [text for text, _ in split] == [text for text, _ in alone]
        assert any("blinds" in str(text).lower() for text, _ in split)
    finally:
        server.close()
    assert partner.pid is None  # closed with the server


def test_a_partner_that_died_is_made_up_for_by_the_server(vocabulary, alone):
    samples = pcm_bytes(BLINDS)
    server = PairedServer(world_prompt(vocabulary))
    try:
        _stretched(server, samples)
        partner = server._partner
        assert partner is not None and partner.pid is not None
        assert server.hear(samples) is not None
        assert server.ask(samples, {"stretch": list(STRETCH)})  # split: the partner has the later paces
        os.kill(partner.pid, signal.SIGKILL)
        found = server.answer()
        assert isinstance(found, list) and [text for text, _ in found] == [text for text, _ in alone]
        # and on: the next stretched hearing is the server's alone
        assert [text for text, _ in _stretched(server, samples)] == [text for text, _ in alone]
    finally:
        server.close()


def test_a_kept_utterance_is_played_at_other_paces_but_not_heard(vocabulary, alone):
    samples = pcm_bytes(BLINDS)
    server = WhisperServer(world_prompt(vocabulary))
    try:
        assert server.keep(samples)
        assert server.ask(samples, {"score": ["put the blinds at seventy five percent"]})
        assert server.answer() == []  # nothing heard, so nothing to score against
        assert server.ask(samples, {"stretch": list(STRETCH)})
        assert [text for text, _ in server.answer()] == [text for text, _ in alone]
    finally:
        server.close()


def test_a_server_without_a_model_answers_a_kept_utterance_with_nothing_and_goes_on(tmp_path):
    samples = pcm_bytes(BLINDS)
    server = WhisperServer("", folder=tmp_path)  # no model.bin there: it warns and answers null
    try:
        assert server.keep(samples)
        assert server.ask(samples, {"stretch": list(STRETCH)})
        assert server.answer() is None
        assert server.pid is not None  # still up
        assert server.ask(samples, {"beam": 2}) and server.answer() == []  # nothing heard
    finally:
        server.close()
