"""Whisper kept loaded between one-shot commands: a small daemon that ``knic say`` asks over a Unix socket.

``knic say`` is a new process for each command. Loading CTranslate2 and the Whisper model took about 0.5 s of
its 1.7 s (median, 20 runs), before Whisper heard anything. The first ``knic say`` of a world therefore hears
with a model of its own, as before, and then leaves this daemon running (:func:`ensure`); the next ones ask it
(:func:`ask`) and skip the load. The daemon serves one world's prompt (the socket's name is a digest of the
prompt, the model folder and this code, :func:`socket_path`), one request at a time, and leaves after
:data:`IDLE_S` seconds without one (``KNIC_WHISPER_IDLE_S``; 0 turns the daemon off).

The socket lives in a folder of the user's own (``$TMPDIR/knic-<uid>``, mode 700): no other user can ask it.
A request is framed audio and nothing else (raw 16 kHz 16-bit PCM, at most :data:`MAX_REQUEST_BYTES`); the
answer is ``[text, mean log-prob]`` as JSON, or null.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import socket
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

from core.errors import LanguageError
from knic.language.whisperpass import FRAME, Heard, WhisperPass, framed_reply, heard_of

#: seconds the daemon waits for a request before it leaves (``KNIC_WHISPER_IDLE_S`` overrides; 0: no daemon)
IDLE_S = 600.0
IDLE_ENV = "KNIC_WHISPER_IDLE_S"
#: the largest request the daemon reads (a WAV file ``knic say`` accepts is at most 32 MiB)
MAX_REQUEST_BYTES = 32 * 1024 * 1024
#: seconds a client waits for the daemon's answer (Whisper takes well under a second per command)
ASK_TIMEOUT_S = 10.0
#: longest socket path the platform takes (108 bytes on Linux, with its terminating zero)
_MAX_PATH = 100


def idle_s() -> float:
    """The daemon's idle time (:data:`IDLE_S`, or ``KNIC_WHISPER_IDLE_S`` when it is a number)."""
    try:
        return max(0.0, float(os.environ.get(IDLE_ENV, IDLE_S)))
    except ValueError:
        return IDLE_S


def _own_folder() -> Path | None:
    """``$TMPDIR/knic-<uid>``, made if missing; None when it is not a private folder of this user's."""
    folder = Path(tempfile.gettempdir()) / f"knic-{os.getuid()}"
    try:
        folder.mkdir(mode=0o700, exist_ok=True)
        info = os.lstat(folder)
    except OSError:
        return None
    private = stat.S_ISDIR(info.st_mode) and info.st_uid == os.getuid() and not info.st_mode & 0o077
    return folder if private else None


def socket_path(prompt: str, folder: Path | str | None) -> Path | None:
    """The daemon's socket for this prompt and model folder (None: no private folder, or a path too long)."""
    own = _own_folder()
    if own is None or folder is None:
        return None
    digest = hashlib.sha256()
    for part in (prompt, str(folder)):
        digest.update(part.encode() + b"\0")
    here = Path(__file__).resolve().parent
    for code in (here / "whisperpass.py", here / "whisperd.py"):
        digest.update(code.read_bytes())
    path = own / f"whisper-{digest.hexdigest()[:16]}.sock"
    return path if len(str(path)) <= _MAX_PATH else None


def _socket_note(world: str, folder: Path | str | None) -> Path | None:
    own = _own_folder()
    if own is None or folder is None or not world.isalnum():
        return None
    model = hashlib.sha256(str(folder).encode()).hexdigest()[:12]
    return own / f"world-{world}-{model}.whisper"


def remembered_socket(world: str, folder: Path | str | None) -> Path | None:
    """The daemon socket noted by :func:`ensure` for a world key (:func:`knic.language.oneshot.world_key`)
    and model folder: a new ``knic say`` asks the daemon before it has read the world's vocabulary (None:
    none noted)."""
    note = _socket_note(world, folder)
    try:
        path = Path(note.read_text(encoding="utf-8")) if note is not None else None
    except OSError:
        return None
    return path if path is not None and note is not None and path.parent == note.parent else None


def _read_frame(conn: socket.socket, limit: int) -> bytes | None:
    """One framed message from ``conn`` (None: cut short, or longer than ``limit``)."""
    header = _read_exactly(conn, FRAME.size)
    if header is None:
        return None
    (size,) = FRAME.unpack(header)
    return _read_exactly(conn, size) if size <= limit else None


def _read_exactly(conn: socket.socket, size: int) -> bytes | None:
    parts, left = [], size
    while left:
        part = conn.recv(min(left, 1 << 20))
        if not part:
            return None
        parts.append(part)
        left -= len(part)
    return b"".join(parts)


def ask(path: Path | None, samples: bytes, timeout: float = ASK_TIMEOUT_S) -> Heard | None:
    """The daemon's hearing of raw 16 kHz 16-bit PCM, or None (no daemon at ``path``, or no answer)."""
    if path is None or idle_s() <= 0:
        return None
    try:
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as conn:
            conn.settimeout(timeout)
            conn.connect(str(path))
            conn.sendall(FRAME.pack(len(samples)) + samples)
            body = _read_frame(conn, MAX_REQUEST_BYTES)
    except OSError:
        return None
    try:
        return heard_of(json.loads(body)) if body is not None else None
    except ValueError:
        return None


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


def ensure(prompt: str, folder: Path | str | None, world: str = "") -> int | None:
    """Start the daemon for this prompt unless one runs or daemons are off (:func:`idle_s`), and note its
    socket for the world key ``world`` (:func:`remembered_socket`); the new process's id, else None. The
    daemon is a session of its own: it outlives the caller, with no terminal and no inherited pipes."""
    path = socket_path(prompt, folder)
    if path is None or idle_s() <= 0:
        return None
    note = _socket_note(world, folder) if world else None
    if note is not None and remembered_socket(world, folder) != path:
        with contextlib.suppress(OSError):
            note.write_text(str(path), encoding="utf-8")
    if running(path):
        return None
    command = [sys.executable, "-m", "knic.language.whisperd", str(path), prompt, str(folder)]
    try:
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


def serve(path: Path, prompt: str, folder: str, idle: float) -> None:
    """The daemon: load the model, listen at ``path`` (taking it over atomically), answer each request, and
    leave after ``idle`` seconds without one or when another daemon took the path over."""
    whisper = WhisperPass(prompt, folder=Path(folder))
    try:
        whisper._load()
    except LanguageError:
        return
    staged = path.with_name(f"{path.name}.{os.getpid()}")
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as listener:
        listener.bind(str(staged))
        os.chmod(staged, 0o600)
        listener.listen(4)
        os.replace(staged, path)
        mine = os.stat(path).st_ino
        listener.settimeout(idle)
        try:
            while _still_mine(path, mine):
                try:
                    conn, _ = listener.accept()
                except TimeoutError:
                    return
                with conn:
                    _answer(conn, whisper)
        finally:
            if _still_mine(path, mine):
                path.unlink(missing_ok=True)


def _still_mine(path: Path, inode: int) -> bool:
    try:
        return os.stat(path).st_ino == inode
    except OSError:
        return False


def _answer(conn: socket.socket, whisper: WhisperPass) -> None:
    """Read one request from ``conn`` and write Whisper's answer (null when it cannot hear it)."""
    conn.settimeout(ASK_TIMEOUT_S)
    try:
        data = _read_frame(conn, MAX_REQUEST_BYTES)
        if data is not None:
            conn.sendall(framed_reply(whisper, data))
    except OSError:
        return


if __name__ == "__main__":  # python -m knic.language.whisperd SOCKET PROMPT FOLDER
    with contextlib.suppress(KeyboardInterrupt):
        serve(Path(sys.argv[1]), sys.argv[2], sys.argv[3], idle_s())
