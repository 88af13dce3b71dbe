"""The goal intake: understand, validate, confirm when the role asks, add all or nothing."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import KnowledgeBaseError
from knic.intake import GoalIntake, Outcome, parse_goals
from knic.language.world import load_world
from knowledge_base import Fact

SPEECH = Path(__file__).resolve().parents[1] / "fixtures" / "speech"


def intake(*, confirm: bool = False) -> tuple[GoalIntake, list[str]]:
    kb, vocabulary = load_world()
    kb.clear_goals()  # the problem file's own goal
    said: list[str] = []
    return GoalIntake(kb, vocabulary, said.append, confirm=confirm), said


def test_an_english_command_becomes_goals_in_one_batch() -> None:
    gi, said = intake()
    reply = gi.submit("locate the tablet and bring it to me")
    assert reply.outcome is Outcome.ADDED
    assert set(map(str, gi.kb.goals())) == {"(reported tablet)", "(has annie tablet)"}
    assert said and said[-1].startswith("You asked me to find the tablet")


def test_pddl_atoms_are_validated_before_anything_is_added() -> None:
    gi, _ = intake()
    reply = gi.submit("(object_at glasses bedroom) (object_at glasses nowhere)")
    assert reply.outcome is Outcome.REFUSED
    assert "nowhere" in reply.reason
    assert gi.kb.goals() == []
    assert gi.submit("(object_at glasses bedroom) (light_on bedroom_left_light)").outcome is Outcome.ADDED
    assert len(gi.kb.goals()) == 2


def test_a_command_the_world_cannot_take_is_refused_with_a_reason() -> None:
    gi, said = intake()
    reply = gi.submit("bring me the unicorn")
    assert reply.outcome is Outcome.REFUSED
    assert gi.kb.goals() == []
    assert said[-1].startswith("Sorry")


def test_a_confirming_role_adds_only_after_a_clear_yes() -> None:
    gi, said = intake(confirm=True)
    assert gi.submit("switch on the bedroom lights").outcome is Outcome.ASKED
    assert said[-1].endswith("Is that right?")
    assert gi.kb.goals() == []
    assert gi.hear("hmm").outcome is Outcome.ASKED_AGAIN
    assert gi.hear("yes please").outcome is Outcome.ADDED
    assert Fact("light_on", ("bedroom_left_light",)) in gi.kb.goals()


def test_no_or_silence_declines_and_adds_nothing() -> None:
    gi, _ = intake(confirm=True)
    gi.submit("bring me my glasses")
    assert gi.hear("no").outcome is Outcome.DECLINED
    gi.submit("bring me my glasses")
    assert gi.hear(None).outcome is Outcome.ASKED_AGAIN
    assert gi.hear(None).outcome is Outcome.DECLINED
    assert gi.kb.goals() == []
    assert [r.outcome for r in gi.history][-1] is Outcome.DECLINED


def test_spoken_commands_go_through_the_same_door() -> None:
    gi, _ = intake()
    wav = sorted(SPEECH.glob("cmd_*.wav"))[0]
    reply = gi.submit_audio(wav)
    assert reply.outcome in (Outcome.ADDED, Outcome.REFUSED)
    assert (reply.outcome is Outcome.ADDED) == bool(gi.kb.goals())


def test_after_please_answer_yes_or_no_the_spoken_reply_is_heard_as_an_answer() -> None:
    """Once the robot asked for a plain yes or no, the reply is heard with the closed answer grammar (no
    non-answer path); the goals are added on its yes."""
    sure = SPEECH.parent / "speech_answers" / "answer_021.wav"  # "sure" (development answer set)
    gi, said = intake(confirm=True)
    gi.submit("switch on the bedroom lights")
    assert gi.hear("hmm").outcome is Outcome.ASKED_AGAIN
    assert said[-1] == "Please answer yes or no."
    assert gi.submit_audio(sure).outcome is Outcome.ADDED
    assert gi.recognise_plain_answer is not None and gi.recognise_answer is None  # heard closed
    assert Fact("light_on", ("bedroom_left_light",)) in gi.kb.goals()


def test_the_closed_answer_grammar_hears_speech_as_an_answer_the_open_one_refuses() -> None:
    from knic.language.speech import AnswerRecognizer

    recognizer = AnswerRecognizer()
    chatter = SPEECH.parent / "speech_ood_dev" / "ood_dev_001.wav"  # "good morning how did you sleep"
    assert recognizer.recognize(chatter) == ""
    assert recognizer.recognize(chatter, closed=True) != ""


@pytest.mark.parametrize("text", ["", "(object_at glasses", "object_at glasses bedroom)", "(a) junk"])
def test_malformed_pddl_is_a_one_line_error(text: str) -> None:
    with pytest.raises(KnowledgeBaseError) as info:
        parse_goals(text)
    assert "\n" not in str(info.value)
