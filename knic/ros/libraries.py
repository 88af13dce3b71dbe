"""The shared libraries of rclpy from PyPI, made reachable only in the processes that use ROS 2.

rclpy's wheels keep their C libraries in the venv's ``lib`` folder and its ``site-packages/ros_*.libs``
folders, which the dynamic loader finds only through ``LD_LIBRARY_PATH``, and the loader reads that variable
when a process starts. Their ``ros-wheels-bootstrapper`` dependency handles this with a ``.pth`` file that
re-executes every Python interpreter of the venv once with the variable set, which costs every ``knic``
command (``knic goal``, ``knic say``) a second interpreter start-up, about 50 ms, for a ROS 2 it never
loads. ``make venv`` therefore removes that ``.pth`` file, and the ROS 2 commands (``knic ros``, ``knic sim
--ros``, ``knic run --ros``, ``knic bench ros``) call :func:`ensure_ros_libraries` first: when the folders
are not on ``LD_LIBRARY_PATH`` it re-executes the command once with them. ``python -m knic.ros.libraries
COMMAND ...`` runs any other command (the test suite: ``make test``) with them.

This module imports nothing of ROS.
"""

from __future__ import annotations

import os
import sys
import sysconfig
from pathlib import Path

#: set in the environment of a process re-executed by :func:`ensure_ros_libraries` (never twice)
GUARD = "KNIC_ROS_LIBRARIES"
#: the bootstrapper's own guard: set too, so that a venv that still has its ``.pth`` does not re-execute again
BOOTSTRAP_GUARD = "_ROS_WHEELS_BOOTSTRAP_COMPLETE"


def library_dirs() -> list[str]:
    """The folders of rclpy's libraries in this environment (none without the ``ros`` extra)."""
    site = Path(sysconfig.get_paths()["purelib"])
    found = sorted(str(p.resolve()) for p in site.glob("ros_*.libs") if p.is_dir())
    if not found:
        return []
    prefix_lib = Path(sys.prefix) / "lib"
    return [str(prefix_lib), *found] if prefix_lib.is_dir() else found


def missing_dirs() -> list[str]:
    """The library folders not yet on ``LD_LIBRARY_PATH``."""
    present = set(filter(None, os.environ.get("LD_LIBRARY_PATH", "").split(os.pathsep)))
    return [d for d in library_dirs() if d not in present]


def ros_environment(base: dict[str, str] | None = None) -> dict[str, str]:
    """A copy of ``base`` (default the process's environment) with the library folders on
    ``LD_LIBRARY_PATH`` (before what it held) and the guards set."""
    env = dict(os.environ if base is None else base)
    present = [p for p in env.get("LD_LIBRARY_PATH", "").split(os.pathsep) if p]
    dirs = [d for d in library_dirs() if d not in present]
    env["LD_LIBRARY_PATH"] = os.pathsep.join([*dirs, *present])
    env[GUARD] = "1"
    env[BOOTSTRAP_GUARD] = "1"
    return env


def ensure_ros_libraries() -> None:
    """Re-execute this command with rclpy's libraries reachable, unless they already are (or there are none,
    or this process already is the re-executed one). Call it before anything has been done: the command
    starts again from the beginning."""
    if not missing_dirs() or os.environ.get(GUARD):
        return
    sys.stdout.flush()
    sys.stderr.flush()
    os.execve(sys.executable, sys.orig_argv, ros_environment())


def main(argv: list[str]) -> int:
    """``python -m knic.ros.libraries COMMAND [ARG ...]``: run COMMAND with rclpy's libraries reachable."""
    if not argv:
        print("usage: python -m knic.ros.libraries COMMAND [ARG ...]", file=sys.stderr)
        return 2
    try:
        os.execvpe(argv[0], argv, ros_environment())
    except OSError as exc:
        print(f"knic.ros.libraries: cannot run {argv[0]!r}: {exc.strerror or exc}", file=sys.stderr)
        return 127
    return 0  # not reached


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
