"""Confirmation questions over ROS 2 (:mod:`knic.ros.questions`): the channel on a real intake and knowledge
base, then across processes (the simulator, ``knic ros`` under the semi-autonomous role, a user)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from knic.intake import GoalIntake, Outcome
from knic.language.vocabulary import Vocabulary
from knic.ros import topics as tp
from knic.ros.convert import MessageError, json_from_ros
from knic.ros.env import ros_context
from knic.ros.questions import QuestionChannel
from knic.seed import seed_kb_from_world
from knic.system.assembly import open_kb
from knic.system.names import ERL_LEXICON
from tests.ros.conftest import Processes
from tests.ros.test_split_run import Watcher
from worlds.api import load_world

GOAL = "(light_on hallway_light)"
PAPER_GOAL = "(object_at glasses bedroom)"
SPOKEN = Path(__file__).resolve().parent / "fixtures" / "spoken_request.yaml"


class Sent:
    """What the channel published on ``/knic/question`` and ``/knic/goal_reply``."""

    def __init__(self) -> None:
        self.questions: list[dict[str, Any]] = []
        self.replies: list[dict[str, Any]] = []


@pytest.fixture
def channel() -> Any:
    kb = open_kb(None, lambda: 0.0)
    seed_kb_from_world(kb, load_world("erl_home"))
    said: list[str] = []
    intake = GoalIntake(kb, Vocabulary.from_knowledge_base(kb, ERL_LEXICON), say=said.append, confirm=True)
    sent = Sent()
    chan = QuestionChannel(
        intake,
        lambda msg: sent.questions.append(json_from_ros(msg)),
        lambda msg: sent.replies.append(json_from_ros(msg)),
        kb.now,
    )
    yield chan, kb, sent, said
    kb.close()


def test_a_question_opens_is_asked_again_and_a_yes_adds_the_goal(channel: Any) -> None:
    chan, kb, sent, said = channel
    reply = chan.submit("switch on the hallway light", speaker="annie", source="ros", request_id=5)
    assert reply.outcome == Outcome.ASKED and not kb.goals()
    asked = sent.questions[-1]
    assert asked["open"] and asked["id"] == chan.open_id and GOAL in asked["goals"]
    assert asked["text"] == said[-1] and asked["text"].endswith("Is that right?")
    # a stale id is refused and changes nothing
    with pytest.raises(MessageError, match="is not open"):
        chan.answer("yes", "q99")
    assert not kb.goals() and chan.open_id == asked["id"]
    # neither yes nor no: asked again under the same id
    chan.answer("purple", asked["id"])
    again = sent.questions[-1]
    assert again["id"] == asked["id"] and again["open"] and again["asks"] == 2
    assert sent.replies[-1]["outcome"] == "asked_again"
    chan.answer("yes", asked["id"])
    assert [str(g) for g in kb.goals()] == [GOAL]
    assert sent.questions[-1] == {**sent.questions[-1], "id": asked["id"], "open": False, "outcome": "added"}
    done = sent.replies[-1]
    assert done["outcome"] == "added" and done["id"] == 5 and done["question"] == asked["id"]
    assert chan.open_id is None


def test_no_declines_and_a_newer_command_replaces_the_question(channel: Any) -> None:
    chan, kb, sent, _ = channel
    chan.submit("switch on the hallway light", speaker="annie", source="ros")
    first = chan.open_id
    chan.submit("(light_on bedroom_left_light)", speaker="annie", source="ros")
    second = chan.open_id
    assert second != first
    closed = [q for q in sent.questions if q["id"] == first and not q["open"]]
    assert closed and closed[0]["outcome"] == "declined" and "newer command" in closed[0]["reason"]
    chan.answer("no", None)
    assert not kb.goals()
    assert sent.questions[-1]["id"] == second and sent.questions[-1]["outcome"] == "declined"
    with pytest.raises(MessageError, match="no question is open"):
        chan.answer("yes", None)


@pytest.mark.timeout(240)
def test_confirmation_over_ros_between_processes(processes: Processes, domain: int) -> None:
    from std_msgs.msg import String

    processes.start("sim", "sim", "--ros", "--world", "erl_home_paper", "--json")
    knic = processes.start(
        "knic", "ros", "--world", "erl_home_paper", "--role", "service_semi_autonomous", "--json"
    )
    with ros_context(domain) as context:
        w = Watcher(context)
        questions: list[Any] = []
        w.node.create_subscription(String, tp.QUESTION, questions.append, tp.reliable(1, latched=True))
        pub_answer = w.node.create_publisher(String, tp.ANSWER, tp.reliable(10))
        w.wait("/knic/facts", lambda: bool(w.got[tp.FACTS]), 120)
        w.send(w.pub_goal, json.dumps({"id": "g1", "text": "bring my glasses to the bedroom"}))
        w.wait("the question and the reply", lambda: bool(questions) and bool(w.got[tp.GOAL_REPLY]), 60)
        question = json_from_ros(questions[-1])
        assert question["open"] and PAPER_GOAL in question["goals"]
        asked = w.latest(tp.GOAL_REPLY)
        assert asked["id"] == "g1" and asked["outcome"] == "asked" and asked["question"] == question["id"]
        # a stale answer: refused in one line, nothing added
        w.send(pub_answer, json.dumps({"id": "q0", "text": "yes"}))
        w.wait("the refusal", lambda: len(w.got[tp.GOAL_REPLY]) >= 2, 60)
        assert w.latest(tp.GOAL_REPLY)["outcome"] == "refused"
        assert "not open" in w.latest(tp.GOAL_REPLY)["reason"]
        w.send(pub_answer, json.dumps({"id": question["id"], "text": "yes please"}))
        w.wait("the answer's reply", lambda: len(w.got[tp.GOAL_REPLY]) >= 3, 60)
        added = w.latest(tp.GOAL_REPLY)
        assert added["id"] == "g1" and added["outcome"] == "added" and added["question"] == question["id"]
        w.wait("the closed question", lambda: not json_from_ros(questions[-1])["open"], 30)
        w.send(w.pub_kb, json.dumps({"id": 3, "op": "goals"}))
        w.wait("the kb reply", lambda: bool(w.got[tp.KB_REPLY]), 60)
        reply = w.latest(tp.KB_REPLY)
        assert reply["id"] == 3 and PAPER_GOAL in reply["result"]
        w.node.destroy_node()
    processes.stop(knic)


@pytest.mark.timeout(240)
def test_spoken_request_and_spoken_yes_over_ros(processes: Processes, domain: int) -> None:
    from std_msgs.msg import String

    with ros_context(domain) as context:
        w = Watcher(context)
        questions: list[Any] = []
        w.node.create_subscription(String, tp.QUESTION, questions.append, tp.reliable(1, latched=True))
        sim = processes.start(
            "sim", "sim", "--ros", "--world", "erl_home_paper", "--scenario", str(SPOKEN), "--json"
        )
        knic = processes.start(
            "knic",
            "ros",
            "--world",
            "erl_home_paper",
            "--role",
            "service_semi_autonomous",
            "--listen",
            "--max-sim-time",
            "300",
            "--json",
        )
        w.wait("the run to end", lambda: knic.poll() is not None, 200)
        for _ in range(20):
            w.executor.spin_once(timeout_sec=0.05)
        w.node.destroy_node()
    assert knic.returncode == 0, processes.errors("knic")
    summary = json.loads(processes.output("knic").strip().splitlines()[-1])
    assert summary["done"] and summary["goals"] == [PAPER_GOAL]
    replies = [json_from_ros(m) for m in w.got[tp.GOAL_REPLY]]
    asked = [r for r in replies if r["outcome"] == "asked"]
    assert asked and asked[0]["source"] == "speech" and asked[0]["text"] == "bring my glasses to the bedroom"
    added = [r for r in replies if r["outcome"] == "added"]
    assert added and added[0]["question"] == asked[0]["question"] and added[0]["text"] == "yes please"
    # the question's own topic is checked in the test above; here the run may end before a loaded machine's
    # discovery delivers it, so only what arrived is checked (the replies above carry the question's id)
    assert not questions or not json_from_ros(questions[-1])["open"]
    assert processes.stop(sim) == 0
    verdict = json.loads(processes.output("sim").strip().splitlines()[-1])
    assert verdict["success"] and PAPER_GOAL in verdict["goals"]
