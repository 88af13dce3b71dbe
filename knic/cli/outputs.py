"""Where a running ``knic run`` writes its outputs, for the commands that follow it.

``knic run --journal FILE`` writes ``.FILE.<pid>.partial`` next to FILE and renames it to FILE when the run
ends (so a refused run never touches an existing FILE). Followers (``knic facts --watch``, ``knic serve``) ask
:func:`running_journal` which file to open: the newest partial file when one is newer than FILE (a run in
progress), else FILE itself. An open SQLite reader keeps following the file across the final rename.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any


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


def component_lines(report: list[dict[str, Any]], real_time_factor: float = 1.0) -> list[str]:
    """``knic run``'s table of the scheduled components (:meth:`knic.scheduler.Scheduler.report`): nominal and
    measured rate, mean and worst wall time per step, and the overruns the scheduler counted (its warnings
    are not printed during the run; they are summed here)."""
    overruns = sum(int(r["overruns"]) for r in report)
    late = [r for r in report if r["overruns"]]
    lines = [
        f"components: {len(report)}, overruns {overruns}"
        + (f" in {len(late)} of them" if late else "")
        + f" (step budget: period / {real_time_factor:g})",
        f"  {'component':<28} {'Hz':>6} {'rate':>7} {'steps':>7} {'mean ms':>8} {'max ms':>8}"
        f" {'slow':>5} {'behind':>6}",
    ]
    for r in report:
        lines.append(
            f"  {r['name']!s:<28} {float(r['frequency']):>6.1f} {float(r['rate']):>7.2f} {int(r['steps']):>7}"
            f" {float(r['mean_ms']):>8.2f} {float(r['max_ms']):>8.1f} {int(r['slow_steps']):>5}"
            f" {int(r['behind']):>6}"
        )
    return lines


def summary(result: Any, commands: list[dict[str, Any]], components: list[dict[str, Any]]) -> dict[str, Any]:
    """The ``--json`` summary of a run (``components``: :meth:`knic.scheduler.Scheduler.report`)."""
    return {
        "success": result.success,
        "reason": result.reason,
        "sim_time": round(result.sim_time, 3),
        "wall_s": round(result.wall_s, 3),
        "goals": result.goals,
        "unconfirmed": result.unconfirmed,
        "plans": result.plans,
        "replans": result.replans,
        "counters": result.counters,
        "commands": commands,
        "components": components,
    }
