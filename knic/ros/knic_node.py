"""KnIC as a ROS 2 node: what it believes, plans and does goes out; goals and knowledge-base requests come in.

Out (:mod:`knic.ros.topics`): ``/knic/facts`` (a JSON snapshot of instances, facts with provenance and goals,
transient local, refreshed at most every ``snapshot_period`` simulated seconds when something changed),
``/knic/fact_events`` (one JSON message per knowledge-base change, published from the change's own
callback), ``/knic/plan`` and ``/knic/trace`` (dispatcher trace events), ``/erlc/command`` (each action the
dispatcher starts), ``/erlc/robot_pose`` (10 Hz), ``/erlc/trajectory`` (each new base path),
``/knic/octomap/<kind>_<name>`` (each tracked entity's octomap, 1 Hz), ``/knic/map`` (the map).

In: ``/knic/goal`` (an English command or PDDL atoms, plain text or JSON ``{"id", "text", "speaker"}``)
through :class:`knic.intake.GoalIntake`, answered on ``/knic/goal_reply``. Roles that confirm ask on
``/knic/question`` and take the answer on ``/knic/answer`` with the question's id
(:mod:`knic.ros.questions`); while a question is open, a text on ``/knic/goal`` that is not PDDL is taken as
the answer too. ``/knic/kb/request`` (JSON ``{"id", "op", ...}``) answered on
``/knic/kb/reply`` with the same ``id``: queries ``facts``, ``holds``, ``why``, ``instances``, ``goals`` and
updates ``add_instance``, ``add_fact``, ``remove_fact``, ``add_goal``, ``remove_goal`` (checked against the
domain: a bad request is answered with one line and changes nothing). Services with standard types:
``/knic/kb/clear_goals`` and ``/knic/kb/problem`` (``std_srvs/Trigger``; the PDDL problem in ``message``).

Threading: everything runs on the run loop's thread: the :class:`KnicBridge` component spins the process's
:class:`~knic.ros.robot.RosLink` at each of its steps and then handles the goals, answers and requests
received, in order, so they are taken between two components, never concurrently with them (and never
inside a spin: answering may speak through a remote robot, which spins for the command's reply).
Knowledge-base changes go out on ``/knic/fact_events`` synchronously, from the change's callback.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from core.errors import KnicError
from knic.intake import IntakeReply, Outcome
from knic.ros import topics as tp
from knic.ros.convert import (
    MessageError,
    grid_to_ros,
    json_from_ros,
    json_to_ros,
    path_to_ros,
    pose_to_ros,
    voxels_to_ros,
)
from knic.ros.questions import QuestionChannel
from knic.ros.robot import RosLink
from knic.scheduler import Component
from knowledge_base import Change, Fact, KnowledgeBase

if TYPE_CHECKING:
    from core.robot import Localisation, Robot
    from knic.intake import GoalIntake
    from knic.kgm2.cognition import CognitiveLayer
    from planner.trace import Trace, TraceEvent
    from worlds.model import World


#: kb request op -> the keys it needs
KB_OPS: dict[str, tuple[str, ...]] = {
    "facts": (),
    "holds": ("fact",),
    "why": ("fact",),
    "instances": (),
    "goals": (),
    "add_instance": ("type", "name"),
    "add_fact": ("fact",),
    "remove_fact": ("fact",),
    "add_goal": ("fact",),
    "remove_goal": ("fact",),
}


def change_to_json(change: Change) -> dict[str, Any]:
    """One knowledge-base change as the JSON of ``/knic/fact_events``."""
    prov = change.provenance
    out: dict[str, Any] = {
        "seq": change.seq,
        "time": change.time,
        "kind": change.kind.value,
        "name": change.name,
        "args": list(change.args),
        "source": prov.source,
        "status": prov.status.value,
        "confidence": prov.confidence,
        "support": list(prov.support),
    }
    if change.fact is not None:
        out["fact"] = str(change.fact)
    if change.value is not None:
        out["value"] = change.value
    return out


def snapshot_to_json(kb: KnowledgeBase) -> dict[str, Any]:
    """The knowledge base now as the JSON of ``/knic/facts``: instances, facts with provenance, goals."""
    state = kb.snapshot()

    def entry(fact: Fact, prov: Any) -> dict[str, Any]:
        return {
            "fact": str(fact),
            "source": prov.source,
            "since": prov.since,
            "status": prov.status.value,
            "confidence": prov.confidence,
        }

    return {
        "seq": state.seq,
        "time": kb.now(),
        "instances": dict(state.instances),
        "facts": [entry(f, p) for f, p in state.facts.items()],
        "goals": [str(g) for g in state.goals],
        "goals_hold": all(state.holds(g) for g in state.goals) if state.goals else False,
    }


class KnicNode:
    """The node ``knic`` (see the module docstring); construct on the run loop's thread.

    Args:
        link: the process's executor.
        kb: the knowledge base.
        trace: the dispatcher's trace (plans, dispatches, outcomes).
        robot: the robot seam (pose estimate and navigation status are republished).
        world: the world (its map goes out as an OccupancyGrid).
        intake: the goal intake, or None to build one (English needs the language package).
        cognition: KGM-2 (its tracks' octomaps go out), or None.
        snapshot_period: simulated seconds between two snapshots on ``/knic/facts`` (when changed).
    """

    def __init__(
        self,
        link: RosLink,
        kb: KnowledgeBase,
        trace: Trace,
        robot: Robot,
        world: World,
        *,
        intake: GoalIntake | None = None,
        cognition: CognitiveLayer | None = None,
        snapshot_period: float = 0.5,
        confirm: bool = False,
    ) -> None:
        from geometry_msgs.msg import PoseStamped
        from nav_msgs.msg import OccupancyGrid, Path
        from std_msgs.msg import String
        from std_srvs.srv import Trigger

        self.link, self.kb, self.trace, self.robot, self.world = link, kb, trace, robot, world
        self.cognition = cognition
        self.snapshot_period = snapshot_period
        self.intake = intake or _intake(kb, robot, world, confirm)
        from rclpy.parameter import Parameter

        # the node's clock follows /clock (simulated time); stamps come from the robot's time base anyway
        n, q = link.node("knic", parameter_overrides=[Parameter("use_sim_time", value=True)]), tp.reliable
        self.node = n
        self.pub_facts = n.create_publisher(String, tp.FACTS, q(1, latched=True))
        # transient local too: a subscriber matched late (discovery can take seconds) asks for what it missed
        self.pub_events = n.create_publisher(String, tp.FACT_EVENTS, q(10000, latched=True))
        self.pub_plan = n.create_publisher(String, tp.PLAN, q(10, latched=True))
        self.pub_trace = n.create_publisher(String, tp.TRACE, q(100))
        self.pub_command = n.create_publisher(String, tp.COMMAND_LOG, q(100))
        self.pub_pose = n.create_publisher(PoseStamped, tp.ROBOT_POSE, q(10))
        self.pub_path = n.create_publisher(Path, tp.TRAJECTORY, q(10, latched=True))
        self.pub_map = n.create_publisher(OccupancyGrid, tp.KNIC_MAP, q(1, latched=True))
        # transient local: a subscriber that joins (or is matched by discovery) late still gets the recent
        # replies; a spoken request in a lockstep run is answered within a second of start-up
        self.pub_goal_reply = n.create_publisher(String, tp.GOAL_REPLY, q(50, latched=True))
        self.pub_kb_reply = n.create_publisher(String, tp.KB_REPLY, q(50))
        self.pub_question = n.create_publisher(String, tp.QUESTION, q(1, latched=True))
        self.questions = QuestionChannel(
            self.intake, self.pub_question.publish, self.pub_goal_reply.publish, kb.now
        )
        self.pub_octomaps: dict[str, Any] = {}
        #: goals, answers and KB requests received, handled in order at the next tick (outside the spin: a
        #: reply may speak, and speaking to a remote robot spins the link for the command's answer)
        self._inbox: deque[tuple[Callable[[Any], None], Any]] = deque()
        n.create_subscription(String, tp.GOAL, self._later(self._on_goal), q(50))
        n.create_subscription(String, tp.KB_REQUEST, self._later(self._on_kb_request), q(50))
        n.create_subscription(String, tp.ANSWER, self._later(self._on_answer), q(50))
        n.create_service(Trigger, tp.KB_CLEAR_GOALS, self._clear_goals)
        n.create_service(Trigger, tp.KB_PROBLEM, self._problem)
        self.events_published = 0
        self._snapshot_seq = -1
        self._next_snapshot = 0.0
        self._path_key: tuple[int, int] | None = None
        self._octomap_digest: dict[str, int] = {}
        #: the simulated time of the latest tick (the stamp of what is published while the run lingers)
        self.last_tick = 0.0
        self._unsubscribe: list[Callable[[], None]] = [
            kb.subscribe(self._on_change),
            trace.subscribe(self._on_trace),
        ]
        self.publish_map()
        self.publish_snapshot()

    # ------------------------------------------------------------------ out

    def _on_change(self, change: Change) -> None:
        self.pub_events.publish(json_to_ros(change_to_json(change)))
        self.events_published += 1

    def _on_trace(self, event: TraceEvent) -> None:
        from planner.trace import EventKind

        record = event.to_dict()
        self.pub_trace.publish(json_to_ros(record))
        if event.kind == EventKind.PLAN and event.plan is not None:
            self.pub_plan.publish(json_to_ros({"time": event.time, "plan": list(event.plan)}))
        elif event.kind == EventKind.DISPATCH and event.action:
            self.pub_command.publish(json_to_ros({"time": event.time, "action": event.action}))

    def publish_snapshot(self) -> None:
        """Publish the knowledge base's snapshot on ``/knic/facts``."""
        self.pub_facts.publish(json_to_ros(snapshot_to_json(self.kb)))
        self._snapshot_seq = self.kb.snapshot().seq

    def publish_map(self) -> None:
        """Publish the world's occupancy grid on ``/knic/map``."""
        from worlds.sim.navigation import GridMap

        grid = GridMap.from_world(self.world)
        self.pub_map.publish(grid_to_ros(grid.occupied, grid.origin, grid.resolution, self.kb.now()))

    def publish_pose(self, localisation: Localisation) -> None:
        """Publish the robot's pose estimate on ``/erlc/robot_pose``."""
        self.pub_pose.publish(pose_to_ros(localisation.robot_pose()))

    def publish_path(self, now: float) -> None:
        """Publish the base's planned path on ``/erlc/trajectory`` when a goal brought a new one."""
        status = self.robot.nav_status()
        key = (status.goal_id, len(status.path))
        if status.path and key != self._path_key:
            self._path_key = key
            self.pub_path.publish(path_to_ros(status.path, now))

    def publish_octomaps(self, now: float) -> None:
        """Publish each tracked entity's octomap (cubes) on ``/knic/octomap/<kind>_<name>`` when changed and
        someone listens (thousands of points cost to convert; a new subscriber gets the next one)."""
        from visualization_msgs.msg import MarkerArray

        if self.cognition is None:
            return
        for track in self.cognition.tracks():
            kind = "people" if track.cls == "person" else "objects"
            topic = tp.octomap_topic(kind, track.symbol)
            if topic not in self.pub_octomaps:
                self.pub_octomaps[topic] = self.node.create_publisher(
                    MarkerArray, topic, tp.reliable(1, latched=True)
                )
            if self.pub_octomaps[topic].get_subscription_count() == 0:
                self._octomap_digest.pop(topic, None)
                continue
            centres = np.asarray(track.octomap.tree.extractPointCloud()[0], dtype=np.float64).reshape(-1, 3)
            digest = hash(centres.round(3).tobytes())
            if self._octomap_digest.get(topic) == digest:
                continue
            self._octomap_digest[topic] = digest
            name = topic.removeprefix(tp.OCTOMAP_PREFIX)
            self.pub_octomaps[topic].publish(
                voxels_to_ros(name, centres, float(track.octomap.resolution), now)
            )

    def tick(self, now: float) -> None:
        """The bridge's periodic work at simulated time ``now`` (see :class:`KnicBridge`)."""
        self.last_tick = now
        self.link.drain()
        self.handle_inbox()
        self.publish_pose(self.robot)
        self.publish_path(now)
        if now >= self._next_snapshot and self.kb.snapshot().seq != self._snapshot_seq:
            self._next_snapshot = now + self.snapshot_period
            self.publish_snapshot()

    # ------------------------------------------------------------------ in

    def _later(self, handler: Callable[[Any], None]) -> Callable[[Any], None]:
        def receive(msg: Any) -> None:
            self._inbox.append((handler, msg))

        return receive

    def handle_inbox(self) -> None:
        """Handle the goals, answers and knowledge-base requests received so far, in arrival order."""
        while self._inbox:
            handler, msg = self._inbox.popleft()
            handler(msg)

    def _on_goal(self, msg: Any) -> None:
        request_id, text, speaker = None, str(msg.data), "annie"
        if text.lstrip().startswith("{"):
            try:
                data = json_from_ros(msg, "goal")
                request_id, text, speaker = (
                    data.get("id"),
                    str(data["text"]),
                    str(data.get("speaker", speaker)),
                )
            except (MessageError, KeyError, AttributeError) as exc:
                self.pub_goal_reply.publish(json_to_ros({"outcome": "refused", "reason": f"goal: {exc}"}))
                return
        self.take(text, speaker=speaker, source="ros", request_id=request_id)

    def take(self, text: str, *, speaker: str, source: str, request_id: Any = None) -> None:
        """A text from a person (``/knic/goal``, or speech the robot heard): the answer to the open
        question when one is open and the text is not PDDL, else a command; the intake's reply goes out on
        ``/knic/goal_reply``."""
        if self.questions.open_id is not None and not text.lstrip().startswith("("):
            self.questions.answer(text)  # publishes its reply
        else:
            reply = self.submit(text, speaker=speaker, source=source, request_id=request_id)
            out = {"text": text, "source": source, **reply.to_dict()}
            if self.questions.open_id is not None and reply.outcome == Outcome.ASKED:
                out["question"] = self.questions.open_id
            if request_id is not None:
                out["id"] = request_id
            self.pub_goal_reply.publish(json_to_ros(out))
        self.publish_snapshot()

    def submit(
        self, text: str, *, speaker: str = "annie", source: str = "ros", request_id: Any = None
    ) -> IntakeReply:
        """Take a command through the intake (as ``/knic/goal`` does); a question it asks goes out on
        ``/knic/question``."""
        return self.questions.submit(text, speaker=speaker, source=source, request_id=request_id)

    def _on_answer(self, msg: Any) -> None:
        self.questions.on_answer(msg)
        self.publish_snapshot()

    def _on_kb_request(self, msg: Any) -> None:
        request_id = None
        try:
            data = json_from_ros(msg, "kb request")
            if not isinstance(data, dict) or "op" not in data:
                raise MessageError('kb request: expected a JSON object with "op"')
            request_id = data.get("id")
            result = self.kb_request(data)
            reply: dict[str, Any] = {"id": request_id, "ok": True, "result": result}
        except KnicError as exc:
            reply = {"id": request_id, "ok": False, "error": str(exc)}
        self.pub_kb_reply.publish(json_to_ros(reply))

    def kb_request(self, data: dict[str, Any]) -> Any:
        """Answer one knowledge-base request (see the module docstring).

        Raises:
            MessageError: unknown op or missing keys; KnowledgeBaseError: the update is invalid (nothing
            changed).
        """
        op = str(data["op"])
        if op not in KB_OPS:
            raise MessageError(f"kb request: op {op!r} unknown; known: {', '.join(KB_OPS)}")
        missing = [k for k in KB_OPS[op] if k not in data]
        if missing:
            raise MessageError(f"kb request {op}: missing {', '.join(missing)}")
        kb = self.kb
        fact = _parse_fact(data["fact"]) if "fact" in KB_OPS[op] else None
        source = "ros"
        if op == "facts":
            pattern = [None if a in (None, "?") else str(a) for a in data.get("args", [])]
            return [str(f) for f in kb.facts(data.get("predicate"), *pattern)]
        if op == "holds" and fact is not None:
            return kb.holds(fact)
        if op == "why" and fact is not None:
            prov = kb.why(fact)
            if prov is None:
                return None
            return {
                "source": prov.source,
                "since": prov.since,
                "status": prov.status.value,
                "confidence": prov.confidence,
            }
        if op == "instances":
            return kb.instances(data.get("type"))
        if op == "goals":
            return [str(g) for g in kb.goals()]
        if op == "add_instance":
            kb.add_instance(str(data["type"]), str(data["name"]), source=source)
            return True
        assert fact is not None
        if op == "add_fact":
            kb.add_fact(fact.predicate, *fact.args, source=source)
        elif op == "remove_fact":
            return kb.remove_fact(fact.predicate, *fact.args, source=source)
        elif op == "add_goal":
            kb.add_goal(fact.predicate, *fact.args, source=source)
        else:
            return kb.remove_goal(fact.predicate, *fact.args, source=source)
        return True

    def _clear_goals(self, request: Any, response: Any) -> Any:
        count = self.kb.clear_goals(source="ros")
        response.success = True
        response.message = f"{count} goals removed"
        return response

    def _problem(self, request: Any, response: Any) -> Any:
        response.success = True
        response.message = self.kb.to_pddl_problem()
        return response

    def close(self) -> None:
        """Stop listening to the knowledge base and the trace (the link destroys the node)."""
        for unsubscribe in self._unsubscribe:
            unsubscribe()
        self._unsubscribe.clear()


def _parse_fact(text: Any) -> Fact:
    from knic.intake import parse_goals

    facts = parse_goals(str(text))
    if len(facts) != 1:
        raise MessageError(f"kb request: {text!r} is not one PDDL atom")
    return facts[0]


def _intake(kb: KnowledgeBase, robot: Robot, world: World, confirm: bool) -> GoalIntake:
    from knic.intake import GoalIntake
    from knic.language.vocabulary import Lexicon, Vocabulary
    from knic.system.names import world_lexicon

    chosen = world_lexicon(world.source)
    names = (Lexicon.load(chosen) if chosen is not None else Lexicon()).with_entrances(
        world.entrances(), world.back_entrances()
    )
    vocabulary = Vocabulary.from_knowledge_base(kb, names, world.device_rooms())
    return GoalIntake(kb, vocabulary, say=robot.say, confirm=confirm)


class HeardSpeech(Component):
    """Speech the robot heard (``/robot/heard`` through :meth:`core.robot.Robot.poll_utterances`) taken by
    the intake as :meth:`KnicNode.take` takes a text: the answer to the open question, else a command of the
    speaker's (``knic ros --listen``). Utterances without words are skipped.

    Args:
        node: the KnIC node.
        frequency: Hz of simulated time.
    """

    name = "heard_speech"

    def __init__(self, node: KnicNode, frequency: float = 10.0) -> None:
        self.node = node
        self.frequency = frequency
        self.taken = 0

    def step(self, now: float) -> None:
        """Take every utterance heard since the previous step, in order."""
        for utterance in self.node.robot.poll_utterances():
            if utterance.text.strip():
                self.taken += 1
                self.node.take(utterance.text, speaker=utterance.speaker, source="speech")


class KnicBridge(Component):
    """The node's scheduled work: take goals and requests, publish pose, path, snapshot (10 Hz) and the
    octomaps (1 Hz), all in simulated time.

    Args:
        node: the KnIC node.
        frequency: Hz of simulated time.
    """

    name = "ros_bridge"

    def __init__(self, node: KnicNode, frequency: float = 10.0) -> None:
        self.node = node
        self.frequency = frequency
        self._next_octomaps = 0.0

    def step(self, now: float) -> None:
        """Spin the link, publish what is due."""
        self.node.tick(now)
        if now >= self._next_octomaps:
            self._next_octomaps = now + 1.0
            self.node.publish_octomaps(now)
