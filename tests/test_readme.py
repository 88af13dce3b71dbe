"""The README's set-up commands are the ones the Makefile and CI really run."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _code_lines() -> list[str]:
    text = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```\n(.*?)```", text, flags=re.S)
    return [line.strip() for block in blocks for line in block.splitlines() if line.strip()]


def test_readme_gives_run_and_test_commands_backed_by_make_targets() -> None:
    lines = _code_lines()
    assert "make run" in lines and "make test" in lines
    makefile = (ROOT / "Makefile").read_text()
    assert re.search(r"^run:", makefile, flags=re.M) and re.search(r"^test:", makefile, flags=re.M)


def test_ci_runs_exactly_the_readme_test_command() -> None:
    ci = [
        line.strip()
        for line in (ROOT / ".ci/run").read_text().splitlines()
        if line.strip() and not line.startswith("#") and not line.startswith(("set ", "cd "))
    ]
    assert ci == ["make test"]
