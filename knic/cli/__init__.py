"""The ``knic`` command line.

Subcommands live in their own modules and are listed explicitly in :data:`COMMANDS`. Each module
provides ``add_arguments(parser)`` and ``run(args) -> int`` and keeps heavy imports inside ``run`` so that
``--help`` is fast. Only the module of the command given is imported (``knic --help`` imports none), so
start-up costs what that command needs and a broken module breaks only its own command. A
:class:`~core.errors.KnicError` becomes one line on stderr and the error's exit code.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from collections.abc import Callable, Sequence

from core.errors import KnicError
from knic import __version__

#: name -> (module, one-line help)
COMMANDS: dict[str, tuple[str, str]] = {
    "run": ("knic.cli.run", "run the whole system in the simulated apartment"),
    "plan": ("knic.cli.plan", "plan a PDDL problem"),
    "facts": ("knic.cli.facts", "show the live or recorded fact base"),
    "world": ("knic.cli.world", "check or render a world file"),
    "goal": ("knic.cli.goal", "turn a text command into PDDL goals"),
    "say": ("knic.cli.say", "turn a spoken command (WAV) into PDDL goals"),
    "listen": ("knic.cli.listen", "listen to a microphone or stream and print the commands heard"),
    "bench": ("knic.cli.bench", "run a benchmark and print its figures"),
    "serve": ("knic.cli.serve", "show the robot's mind live in a browser (facts, why, map, trace, goals)"),
    "ros": ("knic.cli.ros", "run KnIC as a ROS 2 node beside a robot (or knic sim --ros)"),
    "sim": ("knic.cli.sim", "run the simulated apartment as a ROS 2 node (--ros)"),
    "sweep": ("knic.cli.sweep", "run the task suites over seeds and roles and print the success counts"),
}


#: the command line being parsed (set by :func:`main`): which registry entries to import
_ARGV: list[str] = []


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="knic", description="KnIC: knowledge inference and plan execution.")
    parser.add_argument("--version", action="version", version=f"knic {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    add_command_modules(sub, COMMANDS)
    return parser


def add_command_modules(sub: argparse._SubParsersAction, registry: dict[str, tuple[str, str]]) -> None:
    """Add one subparser per registry entry; a module that is missing is reported when the command is used.

    Only the entry named on the command line (:data:`_ARGV`) has its module imported and its arguments
    added; when no entry is named (``--help``) none is imported.
    """
    chosen = next((a for a in _ARGV if not a.startswith("-") and a in registry), None)
    for name, (module_name, help_text) in registry.items():
        command_parser = sub.add_parser(name, help=help_text, description=help_text)
        if _ARGV and name != chosen:
            continue
        try:
            module = importlib.import_module(module_name)
        except ModuleNotFoundError as exc:
            if exc.name != module_name:
                raise
            command_parser.set_defaults(_run=_missing(name, module_name))
            continue
        module.add_arguments(command_parser)
        command_parser.set_defaults(_run=module.run)


def _missing(name: str, module_name: str) -> Callable[[argparse.Namespace], int]:
    def run(args: argparse.Namespace) -> int:
        raise KnicError(f"command {name!r} is not available in this build: module {module_name} is missing")

    return run


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    _ARGV[:] = argv or ["--help"]
    try:
        parser = build_parser()
    finally:
        _ARGV[:] = []
    args = parser.parse_args(argv)
    try:
        code: int = args._run(args)
    except KnicError as exc:
        print(f"knic: error: {exc}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print("knic: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # the reader of our output left ("knic goal - | head -1"): stop quietly
        _drop_stdout()
        return 141  # as a shell reports a process ended by SIGPIPE
    return code


def _drop_stdout() -> None:
    """Point standard output at the null device, so that Python's flush at exit, to a pipe with no reader,
    raises no second error."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # no file descriptor behind stdout (a test's capture): nothing to flush
        pass
    finally:
        os.close(devnull)


if __name__ == "__main__":
    sys.exit(main())
