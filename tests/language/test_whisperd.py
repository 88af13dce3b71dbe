"""The Whisper daemon ``knic say`` leaves running (knic.language.whisperd): it hears what Whisper hears in
this process, answers only its own user's socket, survives a bad request, and leaves when idle."""

from __future__ import annotations

import contextlib
import os
import socket
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from knic.language import whisperd
from knic.language.audio import load_pcm
from knic.language.whisperpass import FRAME, WhisperPass, model_dir, world_prompt
from knic.language.world import read_vocabulary

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
COMMAND = FIXTURES / "speech_people" / "dev" / "dev_002.wav"  # "can you fetch the remote control for me"
WORLD = "0123abcd"  # a world key as knic.language.oneshot.world_key writes them


def _until(check, seconds: float = 60.0) -> bool:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if check():
            return True
        time.sleep(0.05)
    return False


def _gone(pid: int) -> bool:
    with contextlib.suppress(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)  # reap it if it was started by this process
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    return False


@pytest.fixture
def private_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A temporary folder of this test's own, for this process and the daemons it starts."""
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    return tmp_path


@pytest.fixture
def daemon(private_tmp: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[tuple[str, Path, int]]:
    """A daemon for the ERL apartment's prompt that leaves after 4 idle seconds: (prompt, socket, pid)."""
    monkeypatch.setenv(whisperd.IDLE_ENV, "4")
    prompt = world_prompt(read_vocabulary())
    pid = whisperd.ensure(prompt, model_dir(), WORLD)
    path = whisperd.socket_path(prompt, model_dir())
    assert pid is not None and path is not None
    assert _until(lambda: whisperd.running(path)), "the daemon never listened"
    yield prompt, path, pid
    if not _gone(pid):
        os.kill(pid, 9)


def test_the_daemon_hears_what_whisper_hears_here(daemon: tuple[str, Path, int]) -> None:
    prompt, path, _ = daemon
    audio = load_pcm(COMMAND)
    here = WhisperPass(prompt).hear(np.frombuffer(audio, dtype="<i2"))
    assert whisperd.ask(path, audio) == here
    assert "remote" in here.text.lower()
    assert whisperd.remembered_socket(WORLD, model_dir()) == path  # a new knic say finds it by its world
    assert whisperd.ensure(prompt, model_dir(), WORLD) is None  # one daemon per prompt


def test_a_bad_request_gets_no_answer_and_the_next_one_does(daemon: tuple[str, Path, int]) -> None:
    _, path, _ = daemon
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as conn:
        conn.settimeout(10)
        conn.connect(str(path))
        conn.sendall(FRAME.pack(whisperd.MAX_REQUEST_BYTES + 1))  # longer than it reads
        assert conn.recv(16) == b""
    assert whisperd.ask(path, load_pcm(COMMAND)) is not None


def test_the_daemon_leaves_when_idle_and_its_socket_with_it(daemon: tuple[str, Path, int]) -> None:
    _, path, pid = daemon
    assert _until(lambda: _gone(pid), 30.0)
    assert not path.exists() and whisperd.ask(path, load_pcm(COMMAND)) is None


def test_the_socket_folder_is_the_users_alone(private_tmp: Path) -> None:
    path = whisperd.socket_path("a prompt", "/some/model")
    assert path is not None and path.parent == private_tmp / f"knic-{os.getuid()}"
    assert path.parent.stat().st_mode & 0o077 == 0
    path.parent.chmod(0o755)  # opened to others: no daemon is used there
    assert whisperd.socket_path("a prompt", "/some/model") is None


def test_no_daemon_when_turned_off_or_missing(private_tmp: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    assert whisperd.ask(private_tmp / "none.sock", b"\0\0" * 1600) is None
    assert whisperd.remembered_socket(WORLD, model_dir()) is None
    assert whisperd.remembered_socket(WORLD, None) is None
    monkeypatch.setenv(whisperd.IDLE_ENV, "0")
    assert whisperd.ensure("a prompt", model_dir(), WORLD) is None
    assert list((private_tmp / f"knic-{os.getuid()}").iterdir()) == []
