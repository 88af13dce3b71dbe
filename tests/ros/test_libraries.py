"""rclpy's library path is set only for the processes that use ROS 2 (knic.ros.libraries)."""

from __future__ import annotations

import os
import subprocess
import sys

from knic.ros.libraries import GUARD, library_dirs, main, ros_environment

CHECK = "import os; print(os.environ.get('LD_LIBRARY_PATH', ''))"


def test_the_environment_puts_the_library_folders_first_and_keeps_the_rest() -> None:
    env = ros_environment({"LD_LIBRARY_PATH": "/opt/elsewhere", "HOME": "/root"})
    parts = env["LD_LIBRARY_PATH"].split(os.pathsep)
    assert parts[-1] == "/opt/elsewhere" and parts[: len(library_dirs())] == library_dirs()
    assert env[GUARD] == "1" and env["HOME"] == "/root"
    again = ros_environment(env)  # nothing added twice
    assert again["LD_LIBRARY_PATH"] == env["LD_LIBRARY_PATH"]


def test_a_plain_interpreter_does_not_restart_itself_for_ros() -> None:
    """Without the bootstrap's .pth an ordinary command starts once, with the environment it was given."""
    env = {k: v for k, v in os.environ.items() if k not in (GUARD, "LD_LIBRARY_PATH")}
    env["LD_LIBRARY_PATH"] = "/opt/marker"
    out = subprocess.run([sys.executable, "-c", CHECK], env=env, capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "/opt/marker"


def test_the_wrapper_runs_a_command_with_the_folders() -> None:
    env = {k: v for k, v in os.environ.items() if k not in (GUARD, "LD_LIBRARY_PATH")}
    command = [sys.executable, "-m", "knic.ros.libraries", sys.executable, "-c", CHECK]
    out = subprocess.run(command, env=env, capture_output=True, text=True, check=True)
    assert out.stdout.strip().split(os.pathsep)[: len(library_dirs())] == library_dirs()
    assert main([]) == 2
    assert main(["/nonexistent/command"]) == 127
