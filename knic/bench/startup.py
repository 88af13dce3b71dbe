"""``knic bench startup``: how long the one-shot commands take from a cold process to their answer.

Each run is a fresh ``python -m knic`` process timed from its start to its exit, as a user at a shell sees it
(the interpreter's start, the imports, reading the world, hearing or reading, printing):

* ``goal_median_s`` / ``goal_p90_s`` -- ``knic goal TEXT`` over the command texts;
* ``say_first_s`` -- the first ``knic say`` in a new temporary folder: nothing remembered yet (the world's
  command model is built, no say daemon runs);
* ``say_median_s`` / ``say_p90_s`` -- ``knic say WAV`` after it, over the recordings, answered by the say
  daemon the first one left (:mod:`knic.language.sayd`), once it listens;
* ``say_alone_median_s`` -- ``knic say --no-second-opinion WAV``: pocketsphinx alone, without the daemon
  (the command model and the vocabulary remembered).

The recordings are the first ones of the spoken development set ``tests/fixtures/speech_people/dev``; the
texts are their gold transcripts. The runs use a temporary folder of their own (``TMPDIR``), so the user's
remembered models and daemon are neither used nor touched; the daemon the runs start leaves
:data:`DAEMON_IDLE_S` seconds after the last one.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from core.errors import KnicError
from knic.bench.figures import percentile
from knic.language.sayd import IDLE_ENV, OLD_IDLE_ENV, running

FIXTURES = Path(__file__).resolve().parents[2] / "tests" / "fixtures" / "speech_people" / "dev"
#: seconds the say daemon started by the runs stays after the last one
DAEMON_IDLE_S = 20
#: seconds given at most to the daemon to load before the timed runs (it takes about three on the project's
#: 2-core machine; the runs go on without it after that)
DAEMON_LOAD_S = 60.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--runs", type=int, default=20, help="runs of each command (default 20)")
    parser.add_argument("--fixtures", type=Path, default=FIXTURES, help="folder with gold.json and WAV files")


def _timed(command: list[str], env: dict[str, str]) -> float:
    """Wall seconds of one fresh ``python -m knic`` process.

    Raises:
        KnicError: the command failed for another reason than refusing what it heard (exit 4).
    """
    started = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-m", "knic", *command], env=env, capture_output=True, text=True, check=False
    )
    elapsed = time.perf_counter() - started
    if done.returncode not in (0, 4):
        raise KnicError(f"knic {' '.join(command)} failed: {done.stderr.strip().splitlines()[-1:]}")
    return elapsed


def _wait_for_a_daemon(folder: Path) -> None:
    """Wait until a say daemon listens in ``folder`` (at most :data:`DAEMON_LOAD_S` seconds)."""
    deadline = time.monotonic() + DAEMON_LOAD_S
    while time.monotonic() < deadline:
        if any(map(running, folder.glob("knic-*/say-*.sock"))):
            return
        time.sleep(0.05)


def measure(fixtures: Path, runs: int) -> dict[str, Any]:
    """The start-up figures (see the module's docstring).

    Raises:
        KnicError: no usable gold.json in ``fixtures``, or a command failed.
    """
    if runs < 1:
        raise KnicError(f"--runs must be at least 1, not {runs}")
    try:
        gold = json.loads((fixtures / "gold.json").read_text(encoding="utf-8"))
        commands = [u for u in gold["utterances"] if u["in_grammar"]][:runs]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise KnicError(f"{fixtures / 'gold.json'}: cannot read the recordings: {exc}") from exc
    if not commands:
        raise KnicError(f"{fixtures / 'gold.json'}: no commands")
    wavs = [str(fixtures / u["file"]) for u in commands]
    texts = [str(u["text"]) for u in commands]
    # a cancelled child of the last run (its phone-loop pass) may still be removing its own temporary folder
    # in this one while it is cleaned up: that is no error of the benchmark, and what is left is removed after
    with tempfile.TemporaryDirectory(prefix="knic-startup-", ignore_cleanup_errors=True) as folder:
        env = {**os.environ, "TMPDIR": folder, IDLE_ENV: str(DAEMON_IDLE_S)}
        env.pop(OLD_IDLE_ENV, None)
        first = _timed(["say", wavs[0]], env)
        _wait_for_a_daemon(Path(folder))  # the daemon the first run left loads the world
        goal, say, alone = [], [], []
        for i in range(runs):
            goal.append(_timed(["goal", texts[i % len(texts)]], env))
            say.append(_timed(["say", wavs[i % len(wavs)]], env))
            alone.append(_timed(["say", "--no-second-opinion", wavs[i % len(wavs)]], env))
    shutil.rmtree(folder, ignore_errors=True)
    return {
        "runs": runs,
        "goal_median_s": percentile(goal, 0.5),
        "goal_p90_s": percentile(goal, 0.9),
        "say_first_s": round(first, 3),
        "say_median_s": percentile(say, 0.5),
        "say_p90_s": percentile(say, 0.9),
        "say_alone_median_s": percentile(alone, 0.5),
    }


def run(args: argparse.Namespace) -> int:
    figures = measure(args.fixtures, args.runs)
    if args.json:
        print(json.dumps(figures))
    else:
        for key, value in figures.items():
            print(f"{key}: {value}")
    return 0
