"""Where a running ``knic run`` writes its outputs, for the commands that follow it.

``knic run --journal FILE`` writes ``.FILE.<pid>.partial`` next to FILE and renames it to FILE when the run
ends (so a refused run never touches an existing FILE). Followers (``knic facts --watch``, ``knic serve``) ask
:func:`running_journal` which file to open: the newest partial file when one is newer than FILE (a run in
progress), else FILE itself. An open SQLite reader keeps following the file across the final rename.
"""

from __future__ import annotations

import sys
from pathlib import Path


def running_journal(path: Path, *, announce: bool = True) -> Path:
    """The journal to follow for ``path``: a running run's partial file when it is the newest, else ``path``.

    Args:
        path: the ``--journal`` FILE the user named.
        announce: print one line on stderr when a partial file is chosen.

    Returns:
        ``path`` (existing or not: the caller refuses a missing journal) or the newest
        ``.NAME.<pid>.partial`` next to it when that is newer than ``path``.
    """
    partial = sorted(path.parent.glob(f".{path.name}.*.partial"), key=_mtime)
    if partial and (not path.exists() or _mtime(partial[-1]) > _mtime(path)):
        if announce:
            print(f"knic: following the running run's {partial[-1].name}", file=sys.stderr)
        return partial[-1]
    return path


def _mtime(path: Path) -> float:
    try:
        return path.stat().st_mtime
    except OSError:  # a partial file renamed away between the listing and the stat
        return -1.0
