"""The say daemon ``knic say`` leaves (knic.language.sayd): it prints what a say without it prints, a command
is never lost when it is gone, dies or answers nonsense, a changed world gets another daemon, a bad request
leaves it serving, it leaves when idle, and ``KNIC_SAY_IDLE_S=0`` starts none."""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import os
import shutil
import signal
import socket
import struct
import tempfile
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from core.errors import LanguageError
from knic.cli import main
from knic.cli.goal import print_understanding
from knic.language import sayd
from knic.language.audio import load_pcm

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
ACCEPTED = FIXTURES / "speech_people2" / "dev" / "people2_001.wav"  # "bring me the mug"
REFUSED = FIXTURES / "speech_engines_dev" / "engines_dev_045.wav"  # "what is the weather like today"
WORLDS = Path(__file__).resolve().parents[2] / "worlds"


def _until(check: Callable[[], bool], seconds: float = 60.0) -> bool:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if check():
            return True
        time.sleep(0.05)
    return False


def _pid_at(path: Path) -> int | None:
    """The process id of the daemon listening at ``path`` (its peer credentials), else None."""
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as conn:
        try:
            conn.connect(str(path))
        except OSError:
            return None
        pid, _, _ = struct.unpack("3i", conn.getsockopt(socket.SOL_SOCKET, socket.SO_PEERCRED, 12))
    return pid


def _gone(pid: int) -> bool:
    with contextlib.suppress(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)  # reaped, when a say of this process started it
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    return False


class World:
    """A copy of the ERL apartment's problem and lexicon in a temporary folder that is also ``TMPDIR`` (the
    daemons' folder), with the say daemon its first ``knic say`` left."""

    def __init__(self, folder: Path):
        self.folder = folder
        self.problem = folder / "erl_home_problem.pddl"
        shutil.copy(WORLDS / "erl_home" / "erl_home_problem.pddl", self.problem)
        shutil.copy(WORLDS / "erl_home" / "lexicon.yaml", folder / "lexicon.yaml")

    @property
    def options(self) -> list[str]:
        return ["--problem", str(self.problem)]

    def socket(self) -> Path | None:
        """The socket a say in this world asks now."""
        from knic.cli.say import _world_files
        from knic.language.oneshot import world_key

        args = argparse.Namespace(domain=None, world=None, problem=str(self.problem), lexicon=None)
        return sayd.socket_path(world_key(_world_files(args), "auto"), "auto")

    def daemon(self) -> int:
        """The process id of this world's daemon, waited for."""
        path = self.socket()
        assert path is not None and _until(lambda: sayd.running(path)), "no daemon listened"
        pid = _pid_at(path)
        assert pid is not None
        return pid

    def sockets(self) -> list[Path]:
        return sorted((self.folder / f"knic-{os.getuid()}").glob("say-*.sock"))


@pytest.fixture(scope="module")
def world(tmp_path_factory: pytest.TempPathFactory) -> Iterator[World]:
    folder = tmp_path_factory.mktemp("sayd")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("TMPDIR", str(folder))
        patch.setattr(tempfile, "tempdir", str(folder))
        patch.setenv(sayd.IDLE_ENV, "60")
        here = World(folder)
        with contextlib.redirect_stdout(None):
            assert main(["say", str(ACCEPTED), *here.options]) == 0  # nothing remembered, no daemon yet
        here.daemon()
        yield here
        for path in here.sockets():
            pid = _pid_at(path)
            if pid is not None:
                os.kill(pid, signal.SIGTERM)


@pytest.fixture
def asked(world: World, monkeypatch: pytest.MonkeyPatch) -> list[tuple[Path | None, bool]]:
    """The daemon sockets the says of a test asked, and whether an answer came back."""
    monkeypatch.setenv(sayd.IDLE_ENV, "60")
    calls: list[tuple[Path | None, bool]] = []
    ask = sayd.ask

    def asking(path: Path | None, *args: Any) -> dict[str, Any] | None:
        answer = ask(path, *args)
        calls.append((path, answer is not None))
        return answer

    monkeypatch.setattr(sayd, "ask", asking)
    return calls


def _say(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(["say", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def _without_timing(out: str) -> Any:
    data = json.loads(out)
    data["audio"].pop("decode_ms")
    return data


@pytest.mark.parametrize(
    ("wav", "options"), [(ACCEPTED, ["--speaker", "tracy"]), (REFUSED, [])], ids=["accepted", "refused"]
)
def test_a_say_through_the_daemon_prints_what_one_without_it_prints(
    wav: Path,
    options: list[str],
    world: World,
    asked: list[tuple[Path | None, bool]],
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The same JSON (but the decoding time), text, exit code and stderr line; the text a say without the
    daemon prints is that of its JSON object (knic.cli.goal.print_understanding), so it runs once."""
    text = _say(capsys, str(wav), *world.options, *options)
    data = _say(capsys, str(wav), *world.options, *options, "--json")
    monkeypatch.setenv(sayd.IDLE_ENV, "0")  # no daemon asked, none started
    started: list[int | None] = []
    ensure = sayd.ensure
    monkeypatch.setattr(sayd, "ensure", lambda *args: started.append(ensure(*args)))
    alone = _say(capsys, str(wav), *world.options, *options, "--json")
    assert [answered for _, answered in asked] == [True, True] and started == [None]  # not asked at all
    assert text[0] == data[0] == alone[0] == (0 if wav == ACCEPTED else 4)
    assert text[2] == data[2] == alone[2]  # the refusal's one line on stderr
    assert _without_timing(data[1]) == _without_timing(alone[1])
    with contextlib.suppress(LanguageError), contextlib.redirect_stdout(io.StringIO()) as printed:
        print_understanding(json.loads(alone[1]), False)
    assert text[1] == printed.getvalue() and text[1].startswith("heard: ")
    if wav == ACCEPTED:
        assert "goal: (has tracy mug)" in text[1]
    else:  # Whisper judged pocketsphinx's transcript with the daemon's one server (and the partner it
        # starts for the stretched hearings, knic.language.whisperpair), not with servers of each say's own
        assert _whisper_servers_of(world.daemon()) in (1, 2)


def _whisper_servers_of(pid: int) -> int:
    """How many Whisper servers (python -m knic.language.whisperpass) the process ``pid`` runs."""
    count = 0
    for stat_file in Path("/proc").glob("[0-9]*/stat"):
        with contextlib.suppress(OSError, ValueError, IndexError):
            parent = int(stat_file.read_text().rsplit(")", 1)[1].split()[1])
            command = (stat_file.parent / "cmdline").read_bytes().split(b"\0")
            count += parent == pid and b"knic.language.whisperpass" in command
    return count


def test_a_bad_file_is_the_same_error_with_a_daemon(
    world: World, asked: list[tuple[Path | None, bool]], capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    text_file = tmp_path / "command.wav"
    text_file.write_text("bring me my glasses")
    code, out, err = _say(capsys, str(text_file), *world.options)
    assert (code, out, asked) == (2, "", []) and "not a WAV file" in err and err.count("\n") == 1


def _request(path: Path, data: bytes) -> bytes:
    """Send raw bytes to the daemon; what it answered before closing."""
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as conn:
        conn.settimeout(30)
        conn.connect(str(path))
        with contextlib.suppress(OSError):
            conn.sendall(data)
            conn.shutdown(socket.SHUT_WR)
        try:
            return conn.recv(16)
        except ConnectionResetError:  # closed with the request unread
            return b""


def test_a_bad_request_gets_no_answer_and_the_next_one_does(world: World) -> None:
    path = world.socket()
    assert path is not None
    audio = load_pcm(ACCEPTED)
    frame = sayd.FRAME.pack
    for bad in [
        frame(sayd.MAX_HEADER_BYTES + 1),  # a header longer than it reads
        frame(9) + b"not json!" + frame(len(audio)) + audio,
        frame(14) + b'{"speaker": 3}' + frame(len(audio)) + audio,
        frame(2) + b"{}" + frame(sayd.MAX_REQUEST_BYTES + 1),  # more audio than it reads
        frame(2) + b"{}" + frame(3) + b"odd",
        frame(2) + b"{}" + frame(100),  # cut short
    ]:
        assert _request(path, bad) == b""
    answer = sayd.ask(path, audio, None)
    assert answer is not None and answer["goals"] == ["(has annie mug)"]


def _fake_daemon(path: Path, reply: bytes | None) -> threading.Thread:
    """A socket at ``path`` that reads a request and answers ``reply`` (None: closes without a word)."""
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(str(path))
    listener.listen(1)

    def serve() -> None:
        with listener, listener.accept()[0] as conn:
            conn.recv(1 << 16)
            if reply is not None:
                conn.sendall(sayd.FRAME.pack(len(reply)) + reply)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    return thread


@pytest.mark.parametrize("reply", [None, b"not json", b'{"accepted": "yes"}', b"[1, 2]"])
def test_no_answer_or_nonsense_is_none(tmp_path: Path, reply: bytes | None) -> None:
    path = tmp_path / "fake.sock"
    thread = _fake_daemon(path, reply)
    assert sayd.ask(path, b"\0\0" * 1600, None) is None
    thread.join(10)


def test_a_daemon_killed_before_a_say_is_heard_without_and_started_again_and_leaves_when_idle(
    world: World,
    asked: list[tuple[Path | None, bool]],
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    before = world.daemon()
    os.kill(before, signal.SIGKILL)
    assert _until(lambda: _gone(before) or not sayd.running(world.socket()), 10)
    monkeypatch.setenv(sayd.IDLE_ENV, "2")  # the new daemon leaves 2 s after its last request
    code, out, _ = _say(capsys, str(ACCEPTED), *world.options, "--json")
    assert code == 0 and json.loads(out)["goals"] == ["(has annie mug)"]
    assert [answered for _, answered in asked] == [False]
    path, after = world.socket(), world.daemon()  # a new one, at the same socket
    assert after != before and path is not None
    assert _until(lambda: _gone(after), 15) and not path.exists() and world.sockets() == []


def test_a_changed_world_is_never_asked_the_old_daemon(
    world: World,
    asked: list[tuple[Path | None, bool]],
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    old = world.socket()
    world.problem.write_text(world.problem.read_text(encoding="utf-8") + "\n; changed\n", encoding="utf-8")
    assert world.socket() not in (old, None)
    started: list[int | None] = []
    ensure = sayd.ensure
    monkeypatch.setattr(sayd, "ensure", lambda *args: started.append(ensure(*args)))
    monkeypatch.setenv(sayd.IDLE_ENV, "1")
    code, out, _ = _say(capsys, str(ACCEPTED), *world.options)
    assert code == 0 and "goal: (has annie mug)" in out
    assert asked == [(world.socket(), False)] and started[0] is not None  # another daemon, for the new world


def test_a_new_daemon_of_a_world_retires_the_one_before_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The listening loops of two daemons of one place, the second for a changed world: the first leaves
    when the second takes its socket away, and each one's socket and note go with it."""
    monkeypatch.setattr(sayd, "POLL_S", 0.05)
    tmp_path.chmod(0o700)
    first, second = tmp_path / "say-1.sock", tmp_path / "say-2.sock"
    loops = [
        threading.Thread(target=sayd._listen, args=(path, "place", 30.0, lambda conn: None))
        for path in (first, second)
    ]
    loops[0].start()
    assert _until(lambda: sayd.running(first), 10)
    loops[1].start()
    loops[0].join(10)
    assert not loops[0].is_alive() and not first.exists() and sayd.running(second)
    assert (tmp_path / "place-place.say").read_text(encoding="utf-8") == second.name
    second.unlink()  # taken away: the second leaves too
    loops[1].join(10)
    assert not loops[1].is_alive() and not (tmp_path / "place-place.say").exists()


def test_no_daemon_when_turned_off_or_the_folder_is_open(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    path = sayd.socket_path("0123abcd", "auto")
    assert path is not None and path.parent == tmp_path / f"knic-{os.getuid()}"
    assert path.parent.stat().st_mode & 0o077 == 0
    assert sayd.ask(path, b"\0\0" * 1600) is None  # nothing listens
    monkeypatch.setenv(sayd.IDLE_ENV, "0")
    assert sayd.ensure(path, "place", None, "annie", "auto", "0123abcd") is None  # type: ignore[arg-type]
    assert list(path.parent.iterdir()) == []
    monkeypatch.setenv(sayd.IDLE_ENV, "nonsense")
    assert sayd.idle_s() == sayd.IDLE_S
    monkeypatch.delenv(sayd.IDLE_ENV)
    monkeypatch.setenv(sayd.OLD_IDLE_ENV, "0")  # the earlier name still counts
    assert sayd.idle_s() == 0.0
    path.parent.chmod(0o755)  # opened to others: no daemon is used there
    assert sayd.socket_path("0123abcd", "auto") is None


def test_the_socket_follows_the_key_the_acoustic_model_and_whispers_model(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    first = sayd.socket_path("0123abcd", "auto")
    assert first is not None and first == sayd.socket_path("0123abcd", "auto")
    assert sayd.socket_path("0123abce", "auto") != first
    assert sayd.socket_path("0123abcd", "base") != first
    model = tmp_path / "model"
    model.mkdir()
    (model / "model.bin").write_bytes(b"weights")
    monkeypatch.setenv("KNIC_WHISPER_MODEL", str(model))
    other = sayd.socket_path("0123abcd", "auto")
    assert other not in (None, first)
    (model / "model.bin").write_bytes(b"other weights")
    assert sayd.socket_path("0123abcd", "auto") != other


def test_the_client_finds_what_the_world_and_whisper_find() -> None:
    """The say client does not import knic.language.world nor whisperpass: its copies agree with them."""
    from knic.cli import say
    from knic.language.whisperpass import model_dir
    from knic.language.world import DEFAULT_DOMAIN, DEFAULT_PROBLEM, LEXICON_NAME

    assert (say._DEFAULT_DOMAIN, say._DEFAULT_PROBLEM) == (DEFAULT_DOMAIN, DEFAULT_PROBLEM)
    assert say._LEXICON_NAME == LEXICON_NAME and sayd.whisper_folder() == model_dir()
