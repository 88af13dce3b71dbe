# Two entry points for a fresh machine: `make run` (the system in the simulated apartment) and `make test`.
# Each creates .venv and installs the pinned dependencies (requirements.lock) the first time.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed-stamp
GOAL ?= (object_at glasses bedroom)

.PHONY: run test lint venv clean browser

$(STAMP): pyproject.toml requirements.lock
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	# compat: the source folders on sys.path through a plain .pth (the default editable finder's import hook
	# costs every command about 25 ms of start-up)
	$(BIN)/python -m pip install --quiet -c requirements.lock -e '.[dev,web,ros]' --config-settings editable_mode=compat
	# the ROS wheels' bootstrap .pth re-executes every interpreter for ROS 2's library path (about 50 ms per
	# command); only the ROS 2 commands need that path and set it themselves (knic/ros/libraries.py)
	rm -f $(VENV)/lib/python*/site-packages/ros_wheels_bootstrapper.pth
	# byte-compile the sources once: where PYTHONDONTWRITEBYTECODE is set, every CLI start would compile them
	$(BIN)/python -m compileall -q core knic knowledge_base planner actions worlds > /dev/null
	touch $(STAMP)

venv: $(STAMP)

run: $(STAMP)
	$(BIN)/knic run --world erl_home --goal "$(GOAL)" --journal run.sqlite --trace run.jsonl

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .
	$(BIN)/mypy

# The browser tests of the web view drive Debian's chromium through playwright (playwright cannot download
# its own browsers here); installed with apt-get when missing (needs root, as on CI and the dev machines).
CHROMIUM := /usr/bin/chromium

$(CHROMIUM):
	apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium

browser: $(CHROMIUM)

test: lint browser
	$(BIN)/python -m knic.ros.libraries $(BIN)/pytest

clean:
	rm -rf $(VENV) .mypy_cache .pytest_cache .ruff_cache
