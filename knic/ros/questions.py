"""Confirmation questions over ROS 2: the intake's question out on ``/knic/question``, answers in on
``/knic/answer``.

Under a role that confirms (``service_semi_autonomous``) the goal intake repeats a command back with a
question and waits for yes or no (:class:`knic.intake.GoalIntake`). Over ROS 2:

* ``/knic/question`` (``std_msgs/String`` JSON, transient local, depth 1, so a late subscriber sees the
  current state): ``{"id": "q3", "open": true, "text": "You asked me to ... Is that right?", "goals": [...],
  "command": "...", "speaker": "annie", "asks": 1, "time": t}`` when a question opens (``asks`` grows when the
  robot asks again, same ``id``), and ``{"id": "q3", "open": false, "outcome": "added" | "declined",
  "reason": "...", "time": t}`` when it closes (answered, or replaced by a newer command).
* ``/knic/answer`` (``std_msgs/String``): JSON ``{"id": "q3", "text": "yes"}`` (the ``id`` must be the open
  question's: a stale answer is refused and changes nothing) or plain text answering the open question.
  The intake's reply goes out on ``/knic/goal_reply`` with ``"question"`` set to the question's id and,
  when the command came with one, the command's own ``id``: the requester of a goal sees first ``asked``,
  then ``added`` or ``declined`` under its id.

Threading: as the node's, everything runs on the run loop's thread (callbacks inside the link's spin).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from knic.intake import IntakeReply, Outcome
from knic.ros.convert import MessageError, json_from_ros, json_to_ros

if TYPE_CHECKING:
    from knic.intake import GoalIntake

Publish = Callable[[Any], None]


class QuestionChannel:
    """The intake's confirmation questions as ROS 2 messages (see the module docstring).

    Args:
        intake: the goal intake (its ``confirm`` decides whether questions are asked at all).
        publish_question: publishes a ``std_msgs/String`` on ``/knic/question``.
        publish_reply: publishes a ``std_msgs/String`` on ``/knic/goal_reply``.
        now: the knowledge base's clock (simulated seconds in a run).
    """

    def __init__(
        self,
        intake: GoalIntake,
        publish_question: Publish,
        publish_reply: Publish,
        now: Callable[[], float],
    ) -> None:
        self.intake = intake
        self.publish_question = publish_question
        self.publish_reply = publish_reply
        self.now = now
        self._ids = itertools.count(1)
        #: the open question's id and the id of the command it asks about (None: the command had none)
        self.open_id: str | None = None
        self._request_id: Any = None
        self._asks = 0

    def submit(self, text: str, *, speaker: str, source: str, request_id: Any = None) -> IntakeReply:
        """Take a command through the intake; open (or replace) the question when it asks."""
        before = self.intake.awaiting_answer
        reply = self.intake.submit(text, speaker=speaker, source=source)
        pending = self.intake.awaiting_answer
        if self.open_id is not None and before is not None and pending is not before:
            self._close(Outcome.DECLINED, "replaced by a newer command")
        if reply.outcome == Outcome.ASKED and pending is not None:
            self.open_id, self._request_id, self._asks = f"q{next(self._ids)}", request_id, 1
            self._publish_open(reply)
        return reply

    def answer(self, text: str | None, question_id: Any = None) -> IntakeReply:
        """An answer to the open question (``question_id``: the question it answers, None: the open one).
        The reply is published on ``/knic/goal_reply`` and returned.

        Raises:
            MessageError: no question is open, or ``question_id`` is not the open one (nothing changed).
        """
        if self.open_id is None or self.intake.awaiting_answer is None:
            raise MessageError("answer: no question is open")
        if question_id is not None and str(question_id) != self.open_id:
            raise MessageError(
                f"answer: question {question_id!r} is not open (the open one is {self.open_id})"
            )
        qid, request_id = self.open_id, self._request_id
        reply = self.intake.hear(text)
        if reply.outcome == Outcome.ASKED_AGAIN:
            self._asks += 1
            self._publish_open(reply)
        else:
            self._close(reply.outcome, reply.reason)
        out: dict[str, Any] = {"text": text or "", "question": qid, **reply.to_dict()}
        if request_id is not None:
            out["id"] = request_id
        self.publish_reply(json_to_ros(out))
        return reply

    def on_answer(self, msg: Any) -> None:
        """``/knic/answer`` callback: JSON ``{"id", "text"}`` or plain text; a bad one is refused in one line
        on ``/knic/goal_reply`` and changes nothing."""
        raw = str(msg.data)
        question_id: Any = None
        try:
            if raw.lstrip().startswith("{"):
                data = json_from_ros(msg, "answer")
                if not isinstance(data, dict) or not isinstance(data.get("text"), str):
                    raise MessageError('answer: expected a JSON object with a "text" string')
                question_id, text = data.get("id"), data["text"]
            else:
                text = raw
            self.answer(text, question_id)
        except MessageError as exc:
            self.publish_reply(
                json_to_ros({"question": question_id, "outcome": "refused", "goals": [], "reason": str(exc)})
            )

    def _publish_open(self, reply: IntakeReply) -> None:
        submission = self.intake.awaiting_answer
        assert submission is not None
        self.publish_question(
            json_to_ros(
                {
                    "id": self.open_id,
                    "open": True,
                    "text": reply.reply,
                    "goals": [str(g) for g in submission.goals],
                    "command": submission.text,
                    "speaker": submission.speaker,
                    "asks": self._asks,
                    "time": self.now(),
                }
            )
        )

    def _close(self, outcome: Outcome, reason: str) -> None:
        self.publish_question(
            json_to_ros(
                {
                    "id": self.open_id,
                    "open": False,
                    "outcome": outcome.value,
                    "reason": reason,
                    "time": self.now(),
                }
            )
        )
        self.open_id, self._request_id = None, None
