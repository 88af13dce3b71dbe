"""``knic bench startup``: fresh ``knic goal`` and ``knic say`` processes timed, in a folder of their own."""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

import pytest

from core.errors import KnicError
from knic.bench.startup import measure
from knic.cli import main


def test_one_run_of_each_command_prints_every_figure(capsys: pytest.CaptureFixture[str]) -> None:
    before = sorted(Path(tempfile.gettempdir()).glob("knic-oneshot-*"))
    assert main(["bench", "startup", "--runs", "1", "--json"]) == 0
    figures = json.loads(capsys.readouterr().out)
    assert figures["runs"] == 1
    for key in ("goal_median_s", "say_first_s", "say_median_s", "say_alone_median_s"):
        assert figures[key] > 0.0, key
    # the runs kept their models in their own folder, not the user's
    assert sorted(Path(tempfile.gettempdir()).glob("knic-oneshot-*")) == before


def test_bad_arguments_are_one_clear_error(tmp_path: Path) -> None:
    with pytest.raises(KnicError, match="--runs must be at least 1"):
        measure(tmp_path, 0)
    with pytest.raises(KnicError, match=r"gold\.json: cannot read"):
        measure(tmp_path, 1)
