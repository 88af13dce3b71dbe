"""Running episodes: one (episode, baseline) per :func:`run_task`, serially, in worker processes, or on Ray.

:func:`run_task` is the unit of work and a module-level function, so worker processes (``spawn``: each has
its own pybullet) and Ray tasks run exactly what a serial run runs: the same seeds give the same results.
It assembles the run (:class:`~knic.system.KnicSystem` on the episode's world file and scenario), applies
the baseline (:mod:`.baselines`), attaches the :class:`~.recording.Recorder`, starts the episode with a
:data:`Starter`, runs it to the robot's own stop or the 600 s limit, and hands the timeline to the referee.

Starting an episode is one function (:data:`Starter`); the default,
:func:`~.flow.start_with_task_flow`, starts it the way the rulebook does: Annie calls from her tablet, the
robot comes to her room, asks, hears her command (spoken or typed), repeats it back and she answers yes only
when the repetition means her request; every baseline runs the same flow. The run then goes on until the
robot has reported back (or given up) and its goals are settled, or the time limit.
"""

from __future__ import annotations

import json
import logging
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from knic.bench.granny_annie.episodes import Episode
from knic.bench.granny_annie.flow import Dialogue

if TYPE_CHECKING:
    from knic.bench.granny_annie.recording import Recorder
    from knic.system import KnicSystem
    from worlds.model import World


#: simulated seconds between two live judgements of a benchmark run (its score file for ``knic serve``); the
#: final verdict does not depend on it, and each judgement reads the whole timeline so far
LIVE_JUDGE_PERIOD_S = 5.0
#: starts an episode in an assembled system (before it runs); returns what to ask after the run
Starter = Callable[["KnicSystem", Episode, "Recorder"], Callable[[], Dialogue]]


@dataclass(frozen=True)
class Task:
    """One run: an episode under a baseline.

    Attributes:
        episode: the episode (:meth:`Episode.to_dict` form, so it pickles small).
        baseline: ``knic``, ``static`` or ``oracle``.
        role: the robot's role.
        out: the output directory (the episode's world file is in ``out/worlds``).
        max_sim_time: the time limit in simulated seconds.
        record: write the trace, the journal and the bag.
        damage: the damage model file (:mod:`.damage`); None: the shipped one.
    """

    episode: dict[str, Any]
    baseline: str
    role: str
    out: str
    max_sim_time: float = 600.0
    record: bool = True
    damage: str | None = None


def world_file(out: Path, episode: Episode) -> Path:
    """The episode's world file in ``out`` (written by :func:`write_world_files`)."""
    return out / "worlds" / f"{episode.name}.yaml"


def write_world_files(out: Path, episodes: list[Episode]) -> None:
    """Write each episode's world file (items on their episode furniture) into ``out/worlds``."""
    import yaml

    from knic.bench.granny_annie.placement import world_document
    from worlds.api import load_world

    (out / "worlds").mkdir(parents=True, exist_ok=True)
    worlds: dict[str, Any] = {}
    for episode in episodes:
        world = worlds.setdefault(episode.world, load_world(episode.world))
        document = world_document(world, episode.placements)
        world_file(out, episode).write_text(yaml.safe_dump(document, sort_keys=False), encoding="utf-8")


@cache
def known_world(ref: str) -> World:
    """The world as the robot knew it before any episode (name or file), loaded once per process: every
    task of a worker shares it (a :class:`~worlds.model.World` is frozen)."""
    from worlds.api import load_world

    return load_world(ref)


def run_task(task: Task, starter: Starter | None = None) -> dict[str, Any]:
    """Run one (episode, baseline) and return its result (JSON-able): the score sheet and run figures."""
    from core.errors import KnicError
    from knic.bench.granny_annie.baselines import prepare
    from knic.bench.granny_annie.damage import load_damage, shipped_damage
    from knic.bench.granny_annie.flow import start_with_task_flow
    from knic.bench.granny_annie.livescore import LiveScore, score_path
    from knic.bench.granny_annie.recording import Recorder, write_bag
    from knic.bench.granny_annie.referee import judge
    from knic.system import KnicSystem, RunConfig
    from worlds.api import load_world
    from worlds.scenario import scenario_from_dict

    logging.getLogger("knic.scheduler").setLevel(logging.ERROR)
    episode = Episode.from_dict(task.episode)
    out = Path(task.out)
    tag = f"{episode.name}_{task.baseline}"
    world_path = world_file(out, episode)
    world = load_world(world_path)
    scenario = scenario_from_dict(episode.scenario(), world)
    damage = (shipped_damage() if task.damage is None else load_damage(task.damage)).for_world(world)
    trace = journal = None
    if task.record:
        for sub in ("traces", "journals", "bags"):
            (out / sub).mkdir(parents=True, exist_ok=True)
        trace = (out / "traces" / f"{tag}.jsonl").open("w", encoding="utf-8")
        journal = out / "journals" / f"{tag}.sqlite"
    wall0, cpu0 = time.perf_counter(), time.process_time()
    config = RunConfig(
        world=world_path,
        scenario=scenario,
        seed=episode.sim_seed,
        role=task.role,
        max_sim_time=task.max_sim_time,
        journal=journal,
        trace_stream=trace,
    )
    error = None
    try:
        with KnicSystem(config) as system:
            prepare(system, task.baseline, known=known_world(episode.world))
            recorder = Recorder(
                system.sim, system.sim, system.kb, system.pipeline.bus, damage.contact_window_s
            )
            recorder.attach(system.scheduler)
            recorder.sample(0.0)
            took = (starter or start_with_task_flow)(system, episode, recorder)
            from actions.erl.devices import spoken

            live = LiveScore(
                recorder, episode, lambda: took().understood, None, spoken, period_s=LIVE_JUDGE_PERIOD_S
            )
            if journal is not None:  # the running score beside the journal, for knic serve --journal
                live.path = score_path(journal)
                live.attach(system.scheduler)
            run: dict[str, Any] = {"reason": "no goal was taken", "plans": 0, "replans": 0}
            end, finished = system.sim.time, True
            if system.kb.goals() or system.flows:
                try:
                    result = system.run(task.max_sim_time)
                    run = {"reason": result.reason, "plans": result.plans, "replans": result.replans}
                    end = result.sim_time
                    finished = end < task.max_sim_time - 1e-6
                except KnicError as exc:  # a part failed: what happened until then is judged
                    error = f"{type(exc).__name__}: {exc}"
                    end, finished = system.sim.time, True
            dialogue = took()
            understood = dialogue.understood
            run["task"] = dialogue.ending
            timeline = recorder.finish(end, finished=finished, understood=understood)
            recorder.close()
            score = judge(episode, timeline, spoken, damage)
            live.finish(score, end)
            if task.record:
                write_bag(out / "bags" / tag, recorder.recording)
    finally:
        if trace is not None:
            trace.close()
    return {
        "episode": episode.index,
        "baseline": task.baseline,
        "role": task.role,
        "text": episode.text,
        "spoken": episode.audio is not None,
        "understood": list(understood or ()),
        "score": score.to_dict(),
        "run": {**run, "sim_time": round(end, 2), "finished": finished, "error": error},
        "wall_s": round(time.perf_counter() - wall0, 2),
        "cpu_s": round(time.process_time() - cpu0, 2),  # this process's CPU: the run's cost without load
    }


# ----------------------------------------------------------------------------------------------- backends


def _init_worker() -> None:
    logging.getLogger("knic.scheduler").setLevel(logging.ERROR)


def run_tasks(tasks: list[Task], *, workers: int = 1, backend: str = "local") -> Iterator[dict[str, Any]]:
    """Run every task and yield each result as it completes (order of completion).

    Args:
        workers: processes (``local``: spawned worker processes, one pybullet each; 1 runs in this
            process) or Ray CPUs for a local Ray instance.
        backend: ``local`` or ``ray`` (``RAY_ADDRESS`` selects an existing cluster).
    """
    if backend == "ray":
        yield from _run_ray(tasks, workers)
    elif workers <= 1:
        for task in tasks:
            yield run_task(task)
    else:
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor, as_completed

        context = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=_init_worker) as pool:
            futures = [pool.submit(run_task, task) for task in tasks]
            for future in as_completed(futures):
                yield future.result()


def ray_unavailable() -> str | None:
    """Why the Ray backend cannot run here, or None when ``ray`` imports."""
    try:
        import ray  # noqa: F401
    except ImportError as exc:
        return (
            f"the Ray backend needs the optional 'ray' package ({exc}); install it with"
            " pip install -c requirements.lock -e '.[ray]'"
        )
    return None


def _run_ray(tasks: list[Task], workers: int) -> Iterator[dict[str, Any]]:
    from core.errors import KnicError

    reason = ray_unavailable()
    if reason is not None:
        raise KnicError(reason)
    import os

    import ray

    started = False
    if not ray.is_initialized():
        if os.environ.get("RAY_ADDRESS"):
            ray.init(logging_level=logging.ERROR)
        else:
            ray.init(num_cpus=max(1, workers), include_dashboard=False, logging_level=logging.ERROR)
        started = True
    try:
        remote = ray.remote(num_cpus=1)(run_task)
        pending = [remote.remote(task) for task in tasks]
        while pending:
            done, pending = ray.wait(pending, num_returns=1)
            for ref in done:
                yield ray.get(ref)
    finally:
        if started:
            ray.shutdown()


def result_line(result: dict[str, Any]) -> str:
    """One JSON line of a result (the per-episode report)."""
    return json.dumps(result, sort_keys=True)
