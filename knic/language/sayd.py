"""One world's spoken-command recogniser kept loaded between ``knic say`` commands: a daemon asked over a
Unix socket.

``knic say`` is a new process for each command. Without a daemon it forks its decoder passes and Whisper at
once and meanwhile loads the world (:mod:`knic.language.oneshot`): about 0.85-1.0 s median on the project's
2-core machine, of which the interpreter, the imports and the world took 0.3-0.5 s before the recogniser
started, and loading Whisper's model another 0.5 s in its child. The daemon keeps all of it loaded: the
world's vocabulary and reader, pocketsphinx's decoders in worker processes and Whisper's server
(:class:`~knic.language.sayhearing.Hearing`). A ``knic say`` that finds it checks and reads the WAV file as
without it, sends the audio (:func:`ask`) and prints the understanding it gets back, having imported little
more than the command line; one that finds none, or gets no answer, hears the command itself as before and
then starts the daemon (:func:`ensure`). A command is never lost to the daemon.

The socket's name is a digest of what the answer depends on (:func:`socket_path`): the world key
(:func:`~knic.language.oneshot.world_key`: the world's files, the language code including this module, the
acoustic model and the decoder settings), the acoustic model's files, Whisper's model folder and the
interpreter, so a changed world or code is never asked the old daemon. The speaker goes with each request.
One daemon serves a world's files with an acoustic model (its "place", :func:`place_of`): a daemon started
for a changed world retires the one before it, and a lock keeps a second one of the same key from loading.
It answers one request at a time and leaves after :data:`IDLE_S` seconds without one (``KNIC_SAY_IDLE_S``,
or the older ``KNIC_WHISPER_IDLE_S``; 0 turns the daemon off), or soon after its socket was taken away.

The socket lives in a folder of the user's own (``$TMPDIR/knic-<uid>``, mode 700; none is used when that
folder is open to others). A request is two frames, nothing else: a JSON object (the speaker, at most
:data:`MAX_HEADER_BYTES`), then raw 16 kHz 16-bit PCM (at most :data:`MAX_REQUEST_BYTES`). The answer is the
understanding as JSON (:meth:`~knic.language.understanding.Understanding.to_dict`); a malformed request
gets none, and the daemon goes on serving. Nothing received is evaluated: JSON is parsed, audio decoded.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import socket
import stat
import struct
import sys
import tempfile
import time
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from knic.language.sayhearing import Hearing
    from knic.language.vocabulary import Vocabulary

#: seconds the daemon waits for a request before it leaves (``KNIC_SAY_IDLE_S`` overrides; 0: no daemon)
IDLE_S = 600.0
IDLE_ENV = "KNIC_SAY_IDLE_S"
#: the variable's earlier name (when the daemon kept only Whisper loaded), read when the new one is unset
OLD_IDLE_ENV = "KNIC_WHISPER_IDLE_S"
#: the largest audio a request carries (a WAV file ``knic say`` accepts is at most 32 MiB)
MAX_REQUEST_BYTES = 32 * 1024 * 1024
#: the largest request header (a JSON object naming the speaker)
MAX_HEADER_BYTES = 4096
#: the largest answer a client reads (an understanding is a few hundred bytes)
MAX_REPLY_BYTES = 1024 * 1024
#: seconds a client waits for the answer, besides the audio's duration (Whisper takes about 0.3 s a command
#: on the project's 2-core machine; pocketsphinx, when Whisper is unsure, about as long again)
ASK_TIMEOUT_S = 20.0
#: seconds between the daemon's checks that its socket is still its own
POLL_S = 0.5
#: times a new daemon tries the lock, 0.1 s apart, before it leaves to the one holding it
LOCK_TRIES = 20
#: a message: its length, then its bytes
FRAME = struct.Struct("!I")
#: changed when the request or the answer changes shape (part of the socket's name)
PROTOCOL = "knic-say-1"
#: longest socket path the platform takes (108 bytes on Linux, with its terminating zero)
_MAX_PATH = 100
#: the code whose change makes another daemon, besides what the world key reads
_HERE = Path(__file__).resolve().parent
_CODE = [_HERE / "acoustic", _HERE.parents[1] / "core"]


def idle_s() -> float:
    """The daemon's idle time (:data:`IDLE_S`, or ``KNIC_SAY_IDLE_S``, else ``KNIC_WHISPER_IDLE_S``, when it
    is a number)."""
    value = os.environ.get(IDLE_ENV, os.environ.get(OLD_IDLE_ENV, IDLE_S))
    try:
        return max(0.0, float(value))
    except ValueError:
        return IDLE_S


def own_folder() -> Path | None:
    """``$TMPDIR/knic-<uid>``, made if missing; None when it is not a private folder of this user's."""
    folder = Path(tempfile.gettempdir()) / f"knic-{os.getuid()}"
    with contextlib.suppress(OSError):
        folder.mkdir(mode=0o700, exist_ok=True)
    return folder if private(folder) else None


def private(folder: Path) -> bool:
    """Whether ``folder`` is a folder of this user's that no one else may enter."""
    try:
        info = os.lstat(folder)
    except OSError:
        return False
    return stat.S_ISDIR(info.st_mode) and info.st_uid == os.getuid() and not info.st_mode & 0o077


def whisper_folder() -> Path | None:
    """Whisper's model folder (:func:`knic.language.modelfolder.model_dir`)."""
    from knic.language.modelfolder import model_dir

    return model_dir()


def _acoustic_folders(acoustic_model: str | Path) -> list[Path]:
    from knic.language.acoustic import ACOUSTIC_MODELS, NGRAM_SUBFOLDER, ensemble_members

    folders = []
    for member in ensemble_members(acoustic_model):
        named = ACOUSTIC_MODELS.get(member) if isinstance(member, str) else None
        folder = named if named is not None or member in ACOUSTIC_MODELS else Path(member)
        if folder is not None:  # named by its whole path: another folder is another daemon
            folders += [Path(folder).resolve(), Path(folder).resolve() / NGRAM_SUBFOLDER]
    return folders


def _stamp(path: Path) -> bytes:
    """A file's name, size and modification time (a model file is too large to read at each command)."""
    try:
        info = os.stat(path)
    except OSError:
        return f"{path}|-\0".encode()
    return f"{path}|{info.st_size}|{info.st_mtime_ns}\0".encode()


def socket_path(world: str, acoustic_model: str | Path) -> Path | None:
    """The daemon's socket for a world key (:func:`knic.language.oneshot.world_key`, made with the same
    ``acoustic_model``): a digest of the key, the acoustic model's files, Whisper's model, the interpreter and
    the code the key does not read. None: no private folder, no Whisper model, or a path too long."""
    own, whisper = own_folder(), whisper_folder()
    if own is None or whisper is None:
        return None
    digest = hashlib.sha256(f"{PROTOCOL}|{world}|{sys.executable}|{sys.version}\0".encode())
    digest.update(_stamp(whisper / "model.bin"))
    for folder in _acoustic_folders(acoustic_model):
        with contextlib.suppress(OSError):
            for path in sorted(folder.iterdir()):
                digest.update(_stamp(path))
    for code in sorted(p for folder in _CODE for p in folder.glob("*.py")):
        digest.update(code.read_bytes())
    path = own / f"say-{digest.hexdigest()[:20]}.sock"
    return path if len(str(path)) <= _MAX_PATH else None


def place_of(files: Iterable[str | Path | None], acoustic_model: str | Path) -> str:
    """Which world a daemon serves, whatever the content of its files: their paths and the acoustic model
    (a daemon started for the same place retires the one before it)."""
    named = sorted({str(Path(f).resolve()) for f in files if f})
    return hashlib.sha256(json.dumps([named, str(acoustic_model)]).encode()).hexdigest()[:20]


def _read_exactly(conn: socket.socket, size: int) -> bytes | None:
    parts, left = [], size
    while left:
        part = conn.recv(min(left, 1 << 20))
        if not part:
            return None
        parts.append(part)
        left -= len(part)
    return b"".join(parts)


def _read_frame(conn: socket.socket, limit: int) -> bytes | None:
    """One framed message from ``conn`` (None: cut short, or longer than ``limit``)."""
    header = _read_exactly(conn, FRAME.size)
    if header is None:
        return None
    (size,) = FRAME.unpack(header)
    return _read_exactly(conn, size) if size <= limit else None


def _framed(data: bytes) -> bytes:
    return FRAME.pack(len(data)) + data


def ask(path: Path | None, samples: bytes, speaker: str | None = None) -> dict[str, Any] | None:
    """The daemon's understanding of raw 16 kHz 16-bit PCM said by ``speaker`` (None: the world's default),
    or None: no daemon at ``path``, daemons are off, or no answer of the right shape came back (the caller
    then hears the command itself)."""
    if path is None or idle_s() <= 0 or len(samples) > MAX_REQUEST_BYTES:
        return None
    header = json.dumps({"speaker": speaker}).encode()
    try:
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as conn:
            conn.settimeout(ASK_TIMEOUT_S + len(samples) / 32000.0)
            conn.connect(str(path))
            conn.sendall(_framed(header) + _framed(samples))
            body = _read_frame(conn, MAX_REPLY_BYTES)
    except OSError:
        return None
    try:
        return understanding_of(json.loads(body)) if body is not None else None
    except ValueError:
        return None


def understanding_of(data: Any) -> dict[str, Any] | None:
    """An answer that ``knic say`` can print (:func:`knic.cli.goal.print_understanding`), else None."""
    if not isinstance(data, dict) or not isinstance(data.get("accepted"), bool):
        return None
    lists = [data.get("frames"), data.get("goals"), data.get("notes", [])]
    if not all(isinstance(items, list) for items in lists) or not isinstance(data.get("transcript"), str):
        return None
    frames, goals, notes = lists
    shapes = [
        all(isinstance(f, dict) and isinstance(f.get("frame"), str) for f in frames),
        all(isinstance(g, str) for g in [*goals, *notes]),
        data["accepted"] or isinstance(data.get("reason"), str),
        isinstance(data.get("question", ""), str),
    ]
    return data if all(shapes) else None


def running(path: Path | None) -> bool:
    """Whether a daemon listens at ``path``."""
    if path is None:
        return False
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as conn:
        try:
            conn.connect(str(path))
        except OSError:
            return False
    return True


def ensure(
    path: Path | None, place: str, vocabulary: Vocabulary, speaker: str, acoustic_model: str | Path, key: str
) -> int | None:
    """Start the daemon at ``path`` for a world's ``vocabulary`` and default ``speaker`` unless one runs
    there or daemons are off (:func:`idle_s`); the new process's id, else None. The vocabulary goes to it
    as JSON data in the private folder. The daemon is a session of its own: it outlives the caller, with
    no terminal and no inherited pipes."""
    import subprocess

    if path is None or idle_s() <= 0 or running(path):
        return None
    given = path.with_suffix(".json")
    try:
        staged = given.with_name(f"{given.name}.{os.getpid()}")
        staged.write_text(json.dumps({"vocabulary": vocabulary.to_data(), "speaker": speaker}), "utf-8")
        os.replace(staged, given)
        command = [sys.executable, "-m", "knic.language.sayd", str(path), place, str(acoustic_model), key]
        process = subprocess.Popen(
            command,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            start_new_session=True,
        )
    except OSError:
        return None
    return process.pid


def serve(path: Path, place: str, acoustic_model: str, key: str, idle: float) -> None:
    """The daemon: take the socket's lock (another daemon of the same key leaves at once), load the world's
    vocabulary that :func:`ensure` left, build and warm the recogniser, listen at ``path`` (taking it over
    atomically, and retiring the daemon of the same place before it), answer each request, and leave after
    ``idle`` seconds without one or when its socket is taken away."""
    import fcntl

    if idle <= 0 or not place.isalnum() or not private(path.parent):
        return
    lock_file = path.with_suffix(".lock")
    lock = os.open(lock_file, os.O_RDWR | os.O_CREAT, 0o600)
    for attempt in range(LOCK_TRIES):  # a killed daemon's workers let go of its lock a moment later
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            break
        except OSError:
            if attempt == LOCK_TRIES - 1:
                os.close(lock)
                return
            time.sleep(0.1)
    try:
        loaded = _load(path, acoustic_model, key)
        if loaded is not None:
            vocabulary, speaker, hearing = loaded
            try:
                _listen(path, place, idle, lambda conn: _answer(conn, hearing, vocabulary, speaker))
            finally:
                hearing.close()
    finally:
        lock_file.unlink(missing_ok=True)
        os.close(lock)


def _load(path: Path, acoustic_model: str, key: str) -> tuple[Vocabulary, str, Hearing] | None:
    """The vocabulary and default speaker :func:`ensure` left beside the socket, and what hears the world's
    commands (:class:`Hearing`, its workers forked now, before the socket exists, so that they hold no copy
    of it). None: nothing usable was left, or the models cannot be loaded."""
    from core.errors import KnicError
    from knic.language.sayhearing import Hearing
    from knic.language.vocabulary import Vocabulary

    given = path.with_suffix(".json")
    try:
        data = json.loads(given.read_text(encoding="utf-8"))
        vocabulary, speaker = Vocabulary.from_data(data["vocabulary"]), str(data["speaker"])
        return vocabulary, speaker, Hearing(vocabulary, acoustic_model, key)
    except (OSError, ValueError, KeyError, TypeError, RuntimeError, KnicError):
        return None
    finally:
        given.unlink(missing_ok=True)


def _listen(path: Path, place: str, idle: float, answer: Any) -> None:
    """Listen at ``path`` and call ``answer(conn)`` for each connection, until ``idle`` seconds pass without
    one or the socket is no longer this one (another daemon took the path over, or removed it)."""
    staged = path.with_name(f"{path.name}.{os.getpid()}")
    staged.unlink(missing_ok=True)
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as listener:
        listener.bind(str(staged))
        os.chmod(staged, 0o600)
        listener.listen(8)
        os.replace(staged, path)
        mine = os.stat(path).st_ino
        _retire(place, path)
        deadline = time.monotonic() + idle
        try:
            while _still_mine(path, mine):
                left = deadline - time.monotonic()
                if left <= 0:
                    return
                listener.settimeout(min(POLL_S, left))
                try:
                    conn, _ = listener.accept()
                except TimeoutError:
                    continue
                with conn:
                    answer(conn)
                deadline = time.monotonic() + idle
        finally:
            if _still_mine(path, mine):
                path.unlink(missing_ok=True)
            note = path.parent / f"place-{place}.say"
            with contextlib.suppress(OSError):
                if note.read_text(encoding="utf-8") == path.name:
                    note.unlink()


def _retire(place: str, path: Path) -> None:
    """Note ``path`` as the daemon of ``place`` and take the socket of the one noted before away (it leaves
    within :data:`POLL_S` seconds, after the request it may be answering)."""
    note = path.parent / f"place-{place}.say"
    with contextlib.suppress(OSError, ValueError):
        before = path.parent / Path(note.read_text(encoding="utf-8").strip()).name
        if before != path and before.name.startswith("say-") and before.suffix == ".sock":
            before.unlink(missing_ok=True)
    with contextlib.suppress(OSError):
        staged = note.with_name(f"{note.name}.{os.getpid()}")
        staged.write_text(path.name, encoding="utf-8")
        os.replace(staged, note)


def _still_mine(path: Path, inode: int) -> bool:
    try:
        return os.stat(path).st_ino == inode
    except OSError:
        return False


#: seconds the daemon waits for the rest of a request once connected
READ_TIMEOUT_S = 10.0


def _answer(conn: socket.socket, hearing: Hearing, vocabulary: Vocabulary, speaker: str) -> None:
    """Read one request from ``conn`` and write the understanding; a malformed request, or any failure to
    hear it, gets no answer (the client then hears the command itself)."""
    from knic.language.understanding import understand_transcript

    conn.settimeout(READ_TIMEOUT_S)
    try:
        header = _read_frame(conn, MAX_HEADER_BYTES)
        request = json.loads(header) if header is not None else None
        said_by = request.get("speaker") if isinstance(request, dict) else 0
        if not isinstance(said_by, (str, type(None))):
            return
        samples = _read_frame(conn, MAX_REQUEST_BYTES)
        if not samples or len(samples) % 2:
            return
        transcript = hearing.transcript(samples)
        result = understand_transcript(transcript, vocabulary, speaker=said_by or speaker)
        conn.sendall(_framed(json.dumps(result.to_dict()).encode()))
    except Exception:  # whatever went wrong, the daemon goes on serving
        return


def _leave(signum: int, frame: object) -> None:
    raise SystemExit(0)


if __name__ == "__main__":  # python -m knic.language.sayd SOCKET PLACE ACOUSTIC_MODEL WORLD_KEY
    import signal

    signal.signal(signal.SIGTERM, _leave)
    with contextlib.suppress(KeyboardInterrupt):
        serve(Path(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4], idle_s())
