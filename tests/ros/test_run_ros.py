"""``knic run --ros``: the single-process run, also on ROS 2; a watcher in another process sees its events,
plans, path and an entity octomap."""

from __future__ import annotations

import pytest

from knic.ros import topics as tp
from knic.ros.convert import json_from_ros, path_from_ros, voxels_from_ros
from knic.ros.env import ros_context
from tests.ros.conftest import Processes
from tests.ros.test_split_run import GOAL, Watcher


@pytest.mark.timeout(200)
def test_run_with_ros_publishes_what_it_does(processes: Processes, domain: int) -> None:
    from nav_msgs.msg import Path
    from visualization_msgs.msg import MarkerArray

    with ros_context(domain) as context:
        w = Watcher(context)
        paths: list[Path] = []
        octomaps: list[MarkerArray] = []
        w.node.create_subscription(Path, tp.TRAJECTORY, paths.append, tp.reliable(10, latched=True))
        topic = tp.octomap_topic("objects", "glasses")
        w.node.create_subscription(MarkerArray, topic, octomaps.append, tp.reliable(1, latched=True))
        args = ["--world", "erl_home_paper", "--goal", GOAL, "--ros", "--linger", "15", "--json"]
        run = processes.start("run", "run", *args)

        def goal_reached() -> bool:
            events = (json_from_ros(m) for m in w.got[tp.FACT_EVENTS])
            return any(e.get("fact") == GOAL and e["kind"] == "add_fact" for e in events)

        # everything is waited for while the run's node lingers after its work: once it has gone, latched
        # messages no longer reach a watcher whose discovery came late (on a busy machine the path and the
        # octomap were missed so, after the fact event had come)
        def failed() -> bool:
            return run.poll() not in (None, 0)

        w.wait("the goal's fact event", lambda: goal_reached() or failed(), 180)
        assert not failed(), processes.errors("run")
        w.wait("the path and the glasses' octomap", lambda: bool(paths) and bool(octomaps), 30)
        w.wait("the run to end", lambda: run.poll() is not None, 60)
        assert run.returncode == 0, processes.errors("run")
        for _ in range(20):
            w.executor.spin_once(timeout_sec=0.05)
        w.node.destroy_node()
    events = [json_from_ros(m) for m in w.got[tp.FACT_EVENTS]]
    assert [e["seq"] for e in events] == sorted(e["seq"] for e in events)  # in the knowledge base's order
    assert any("(pick r2d2 glasses entrance)" in json_from_ros(m)["plan"] for m in w.got[tp.PLAN])
    assert paths and len(path_from_ros(paths[-1])) >= 2
    assert octomaps, "no octomap of the glasses"
    name, centres, resolution = voxels_from_ros(octomaps[-1])
    assert name == "objects_glasses" and len(centres) > 0 and resolution > 0
