"""The benchmark's report: per-episode results and per-baseline summaries as JSON, Markdown tables and plots.

Files written into the output directory:

* ``report.json``: the configuration, the episodes, every (episode, baseline) result, the summary per baseline
  (:func:`~.referee.summarise`) and the ranking (per episode the baselines are ranked as the ERL sheet says;
  ``mean_rank`` and ``wins`` per baseline);
* ``report.md``: the same as tables;
* ``achievements.png`` (share of each achievement kind per baseline), ``time.png`` (time to complete per
  baseline), ``failures.png`` (achievements missed by kind, penalties and disqualifications per baseline).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from knic.bench.granny_annie.referee import DISQUALIFICATIONS, KINDS, PENALTIES, Score, rank_key, summarise


def score_of(result: dict[str, Any]) -> Score:
    """The :class:`Score` of a result's ``score`` dict."""
    s = result["score"]
    return Score(s["achieved"], s["achievable"], s["penalties"], s["disqualifications"], s["time_s"])


def summary(results: list[dict[str, Any]], baselines: list[str]) -> dict[str, dict[str, Any]]:
    """Per baseline, the totals of its results (:func:`~.referee.summarise`), how its runs ended
    (``run_ends``: done, gave_up, time_limit, not_understood, error) and what its runs cost (``cost``: mean
    wall seconds and mean and total CPU seconds of the process that ran them; CPU time predicts the wall
    time of a run on a quiet machine, wall time depends on the load)."""
    out = {}
    for b in baselines:
        mine = [r for r in results if r["baseline"] == b]
        figures = summarise([score_of(r) for r in mine])
        ends = dict.fromkeys(("done", "gave_up", "time_limit", "not_understood", "error"), 0)
        for r in mine:
            ends[run_end(r)] += 1
        figures["run_ends"] = ends
        walls = [float(r["wall_s"]) for r in mine if "wall_s" in r]
        cpus = [float(r["cpu_s"]) for r in mine if "cpu_s" in r]
        figures["cost"] = {
            "wall_s_mean": round(sum(walls) / len(walls), 2) if walls else None,
            "cpu_s_mean": round(sum(cpus) / len(cpus), 2) if cpus else None,
            "cpu_s_total": round(sum(cpus), 2) if cpus else None,
        }
        out[b] = figures
    return out


def run_end(result: dict[str, Any]) -> str:
    """How a run ended: ``error`` (a part failed), ``time_limit``, ``not_understood`` (no goal taken),
    ``gave_up`` (the robot dropped a goal) or ``done`` (it believed every goal achieved); ``task`` is how
    the task flow ended (``done``, ``partly``, ``not understood``, or its phase)."""
    run = result["run"]
    if run.get("error"):
        return "error"
    if not run["finished"]:
        return "time_limit"
    if run["reason"] == "no goal was taken" or run.get("task") == "not understood":
        return "not_understood"
    if "dropped" in run["reason"]:
        return "gave_up"
    return "done"


def ranking(results: list[dict[str, Any]], baselines: list[str]) -> dict[str, dict[str, float]]:
    """Per baseline: mean rank over the episodes (1 = best, ties share the better rank) and episodes won."""
    by_episode: dict[int, dict[str, Score]] = {}
    for r in results:
        by_episode.setdefault(r["episode"], {})[r["baseline"]] = score_of(r)
    ranks: dict[str, list[int]] = {b: [] for b in baselines}
    wins = dict.fromkeys(baselines, 0)
    for scores in by_episode.values():
        keys = {b: rank_key(s) for b, s in scores.items()}
        for b, key in keys.items():
            rank = 1 + sum(other < key for other in keys.values())
            ranks[b].append(rank)
            wins[b] += rank == 1
    return {
        b: {"mean_rank": round(sum(r) / len(r), 3) if r else 0.0, "wins": wins[b]} for b, r in ranks.items()
    }


def write_report(
    out: Path,
    *,
    config: dict[str, Any],
    episodes: list[dict[str, Any]],
    results: list[dict[str, Any]],
    baselines: list[str],
    wall_s: float,
) -> dict[str, Any]:
    """Write report.json, report.md and the plots into ``out``; return the report."""
    results = sorted(results, key=lambda r: (r["episode"], baselines.index(r["baseline"])))
    report = {
        "config": config,
        "summary": summary(results, baselines),
        "ranking": ranking(results, baselines),
        "wall_s": round(wall_s, 1),
        "episodes": episodes,
        "results": results,
    }
    out.mkdir(parents=True, exist_ok=True)
    (out / "report.json").write_text(json.dumps(report, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    (out / "report.md").write_text(markdown(report, baselines), encoding="utf-8")
    plot(out, report, baselines)
    return report


def markdown(report: dict[str, Any], baselines: list[str]) -> str:
    """The report as Markdown tables."""
    cfg = report["config"]
    lines = [
        "# Granny Annie benchmark",
        "",
        f"World `{cfg['world']}` serving `{cfg.get('person', 'annie')}`, {cfg['episodes']} episodes from seed"
        f" {cfg['seed']}, role `{cfg['role']}`, {report['wall_s']} s wall.",
        "",
        "## Summary",
        "",
        "| baseline | achievements | "
        + " | ".join(KINDS)
        + " | penalties | disqualified runs | median time s |"
        " mean rank | wins | run ends |",
        "|---" * (len(KINDS) + 8) + "|",
    ]
    for b in baselines:
        s, r = report["summary"][b], report["ranking"][b]
        kinds = " | ".join(
            f"{s['achievements'][k]['achieved']}/{s['achievements'][k]['achievable']}" for k in KINDS
        )
        penalties = ", ".join(f"{k} {v}" for k, v in s["penalties"].items())
        lines.append(
            f"| {b} | {s['achievements_share']} | {kinds} | {penalties} | {s['disqualified_runs']} |"
            f" {s['time_median_s']} | {r['mean_rank']} | {r['wins']} |"
            f" {', '.join(f'{k} {v}' for k, v in s['run_ends'].items() if v)} |"
        )
    lines += [
        "",
        "## Episodes",
        "",
        "| episode | command | " + " | ".join(baselines) + " |",
        "|---" * (2 + len(baselines)) + "|",
    ]
    by_key = {(r["episode"], r["baseline"]): r for r in report["results"]}
    for ep in report["episodes"]:
        spoken = " (spoken)" if ep.get("audio") else ""
        cells = []
        for b in baselines:
            r = by_key.get((ep["index"], b))
            if r is None:
                cells.append("")
                continue
            s = r["score"]
            mark = " DQ" if s["disqualified"] else ""
            pen = sum(s["penalties"].values())
            cells.append(f"{s['achievements']}/{s['possible']}, {pen} pen., {s['time_s']} s{mark}")
        lines.append(f"| {ep['index']} | {ep['text']}{spoken} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def plot(out: Path, report: dict[str, Any], baselines: list[str]) -> None:
    """achievements.png, time.png and failures.png (matplotlib, no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    summaries = report["summary"]
    width = 0.8 / max(1, len(baselines))
    fig, ax = plt.subplots(figsize=(9, 4))
    for i, b in enumerate(baselines):
        ach = summaries[b]["achievements"]
        shares = [ach[k]["achieved"] / ach[k]["achievable"] if ach[k]["achievable"] else 0.0 for k in KINDS]
        ax.bar([x + i * width for x in range(len(KINDS))], shares, width, label=b)
    ax.set_xticks([x + width * (len(baselines) - 1) / 2 for x in range(len(KINDS))], list(KINDS))
    ax.set_ylabel("share achieved")
    ax.set_ylim(0, 1.05)
    ax.set_title("Achievements per baseline")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "achievements.png", dpi=100)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4))
    times = [[r["score"]["time_s"] for r in report["results"] if r["baseline"] == b] for b in baselines]
    ax.boxplot(times, tick_labels=baselines)
    ax.set_ylabel("simulated seconds")
    ax.set_title("Time to complete")
    fig.tight_layout()
    fig.savefig(out / "time.png", dpi=100)
    plt.close(fig)

    causes = [f"missed {k}" for k in KINDS] + list(PENALTIES) + list(DISQUALIFICATIONS)
    fig, ax = plt.subplots(figsize=(9, 4))
    bottom = [0.0] * len(baselines)
    for cause in causes:
        values = []
        for b in baselines:
            s = summaries[b]
            if cause.startswith("missed "):
                a = s["achievements"][cause[7:]]
                values.append(float(a["achievable"] - a["achieved"]))
            elif cause in s["penalties"]:
                values.append(float(s["penalties"][cause]))
            else:
                values.append(float(s["disqualifications"][cause]))
        if any(values):
            ax.bar(baselines, values, bottom=bottom, label=cause)
            bottom = [x + y for x, y in zip(bottom, values, strict=True)]
    ax.set_ylabel("occurrences over all episodes")
    ax.set_title("Failure causes")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "failures.png", dpi=100)
    plt.close(fig)
