"""``knic bench reliability``, small sizes: fuzzed boundaries never crash, a killed writer loses nothing."""

from __future__ import annotations

import pytest

from knic.bench.reliability import durability, fuzz_all
from knic.cli import main


def test_fuzzed_boundaries_refuse_with_one_line_errors_and_never_crash() -> None:
    results = fuzz_all(20, seed=3)  # the PDDL cases parse with unified-planning: about 1 s each
    assert set(results) == {"pddl_loader", "world_loader", "goal_parser", "kb_api"}
    for name, tally in results.items():
        assert tally["cases"] == 20, name
        assert tally["crashed"] == 0, (name, tally["first_crash"])
        assert tally["accepted"] + tally["handled"] == 20, name
    assert results["pddl_loader"]["handled"] > 0 and results["pddl_loader"]["accepted"] > 0


def test_sigkilled_writer_loses_no_acknowledged_write() -> None:
    figures = durability(kills=2, seed=1)
    assert figures["acknowledged"] > 0
    assert figures["lost_acknowledged"] == 0 and figures["reopen_failures"] == 0


@pytest.mark.parametrize(
    ("argv", "why"),
    [
        (["--parts", "fuzz,nope"], "--parts takes fuzz,durability,faults,soak"),
        (["--soak-s", "nan"], "--soak-s must be a number of seconds >= 0"),
        (["--soak-s", "-5"], "--soak-s must be a number of seconds >= 0"),
    ],
)
def test_bad_options_are_one_line_errors(
    capsys: pytest.CaptureFixture[str], argv: list[str], why: str
) -> None:
    assert main(["bench", "reliability", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert why in err and "\n" not in err
