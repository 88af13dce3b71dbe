"""``knic serve`` from the command line: refusals in one line, a served journal, a running run's journal."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

from knic.cli.serve import running_journal
from tests.web.conftest import Writer


def knic(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "knic", *args], capture_output=True, text=True, timeout=120)


def test_refusals_are_one_line_and_nothing_is_served(tmp_path: Path, writer: Writer) -> None:
    missing = knic("serve", "--journal", str(tmp_path / "none.sqlite"), "--seconds", "1")
    assert missing.returncode != 0 and missing.stderr.strip().endswith("none.sqlite: no such journal file")
    assert "\n" not in missing.stderr.strip()
    exposed = knic("serve", "--journal", str(writer.journal), "--host", "0.0.0.0", "--seconds", "1")
    assert exposed.returncode != 0
    assert exposed.stderr.strip() == (
        "knic: error: --host 0.0.0.0: serving beyond loopback needs --token (every API request must carry it)"
    )
    short = knic("serve", "--journal", str(writer.journal), "--token", "short", "--seconds", "1")
    assert short.stderr.strip() == "knic: error: --token: use at least 16 characters"


def test_serves_a_journal_for_a_while(writer: Writer) -> None:
    done = knic("serve", "--journal", str(writer.journal), "--port", "0", "--seconds", "0.5", "--json")
    assert done.returncode == 0, done.stderr
    url = json.loads(done.stdout)["url"]
    assert url.startswith("http://127.0.0.1:") and not url.endswith(":0/")


def test_a_running_runs_staged_journal_is_followed(tmp_path: Path, writer: Writer) -> None:
    final = tmp_path / "run2.sqlite"
    assert running_journal(final) == final  # nothing running: the path itself (refused later if missing)
    staged = tmp_path / ".run2.sqlite.4242.partial"
    shutil.copy(writer.journal, staged)
    assert running_journal(final) == staged
    final.write_bytes(staged.read_bytes())
    assert running_journal(final) == final


def test_a_new_run_is_followed_over_the_last_runs_journal(tmp_path: Path, writer: Writer) -> None:
    final = tmp_path / "run3.sqlite"
    shutil.copy(writer.journal, final)  # the journal the previous run left
    staged = tmp_path / ".run3.sqlite.4343.partial"
    shutil.copy(writer.journal, staged)
    os.utime(final, (1_000_000, 1_000_000))
    os.utime(staged, (2_000_000, 2_000_000))
    assert running_journal(final) == staged  # the run in progress, not the stale file
    os.utime(final, (3_000_000, 3_000_000))
    assert running_journal(final) == final  # a left-over partial older than the journal is ignored
