"""Whether ROS 2 (rclpy from PyPI) is usable here, and one rclpy context per node process.

rclpy from PyPI needs its shared libraries on ``LD_LIBRARY_PATH``, set only for the processes that use ROS 2
(:mod:`knic.ros.libraries`: the ROS commands re-execute themselves once with it; ``make test`` runs the
suite with it). Nothing is to be set by hand; ``AMENT_PREFIX_PATH`` is not needed (the messages' type support
loads as Python extension modules). A child process started with a copy of the environment inherits the
paths. Where they are missing, :func:`require_ros` says so in one line.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from core.errors import KnicError


class RosUnavailable(KnicError):
    """rclpy or a message package cannot be imported (the ``ros`` extra is missing or broken)."""

    exit_code = 2


def require_ros() -> None:
    """Import rclpy and the message packages the adapter uses.

    Raises:
        RosUnavailable: one line naming what is missing and how to install it.
    """
    try:
        import geometry_msgs.msg  # noqa: F401
        import nav_msgs.msg  # noqa: F401
        import rclpy  # noqa: F401
        import rosgraph_msgs.msg  # noqa: F401
        import sensor_msgs.msg  # noqa: F401
        import std_msgs.msg  # noqa: F401
        import std_srvs.srv  # noqa: F401
        import visualization_msgs.msg  # noqa: F401
    except ImportError as exc:
        detail = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        if "cannot open shared object" in detail:
            hint = "its libraries are not on LD_LIBRARY_PATH: run through python -m knic.ros.libraries"
        else:
            hint = "install the extra: pip install -e '.[ros]'"
        raise RosUnavailable(f"ROS 2 is not usable here ({detail}); {hint}") from None


def domain_id(value: int | None = None) -> int:
    """The DDS domain: ``value``, else ``ROS_DOMAIN_ID``, else 0.

    Raises:
        KnicError: not an integer in 0..232 (what ROS 2 accepts on Linux).
    """
    raw: Any = value if value is not None else os.environ.get("ROS_DOMAIN_ID", "0") or "0"
    try:
        number = int(raw)
    except ValueError:
        raise KnicError(f"ROS_DOMAIN_ID {raw!r} is not an integer") from None
    if not 0 <= number <= 232:
        raise KnicError(f"ROS domain id {number} is outside 0..232")
    return number


@contextmanager
def ros_context(domain: int | None = None) -> Iterator[Any]:
    """An initialised rclpy ``Context`` on ``domain`` (see :func:`domain_id`), shut down on exit.

    Each node process (or test) uses its own context, so several can live in one interpreter.
    """
    require_ros()
    import rclpy
    from rclpy.context import Context
    from rclpy.signals import SignalHandlerOptions

    context = Context()
    # Ctrl-C and SIGTERM are the command line's to handle (they end a run cleanly), not rclpy's
    rclpy.init(context=context, domain_id=domain_id(domain), signal_handler_options=SignalHandlerOptions.NO)
    try:
        yield context
    finally:
        if context.ok():
            context.try_shutdown()


def make_node(name: str, context: Any, **kwargs: Any) -> Any:
    """An rclpy ``Node`` in ``context`` whose publishers and subscriptions have no QoS event handlers unless
    given (``event_callbacks``), and without parameter services unless asked (``start_parameter_services``).

    rclpy's default handlers (a warning on incompatible QoS) are waitables that every executor wait rebuilds:
    with the adapter's forty-odd topics they cost about 1.5 ms per ``spin_once``, which the lockstep split run
    pays several times per simulated step. Without them, a QoS mismatch shows as no messages
    (``ros2 topic info -v`` tells why).
    """
    from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
    from rclpy.node import Node

    class LeanNode(Node):
        def create_publisher(self, *args: Any, **kw: Any) -> Any:
            kw.setdefault("event_callbacks", PublisherEventCallbacks(use_default_callbacks=False))
            return super().create_publisher(*args, **kw)

        def create_subscription(self, *args: Any, **kw: Any) -> Any:
            kw.setdefault("event_callbacks", SubscriptionEventCallbacks(use_default_callbacks=False))
            return super().create_subscription(*args, **kw)

    kwargs.setdefault("start_parameter_services", False)
    return LeanNode(name, context=context, **kwargs)


def make_executor(context: Any) -> Any:
    """The executor a node process spins on one thread: rclpy's ``EventsExecutor`` (callbacks queued by the
    middleware's events, so a ``spin_once`` costs about 0.1 ms instead of the 0.6 ms the
    ``SingleThreadedExecutor`` spends rebuilding its wait set), or the ``SingleThreadedExecutor`` when
    ``KNIC_ROS_EXECUTOR=single`` (or rclpy has no events executor)."""
    if os.environ.get("KNIC_ROS_EXECUTOR", "events") != "single":
        try:
            from rclpy.experimental import EventsExecutor
        except ImportError:
            pass
        else:
            return EventsExecutor(context=context)
    from rclpy.executors import SingleThreadedExecutor

    return SingleThreadedExecutor(context=context)
