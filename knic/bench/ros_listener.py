"""The subscriber process of ``knic bench ros``: receives ``/knic/fact_events`` in a process of its own.

Run as ``python -m knic.bench.ros_listener DOMAIN``. It subscribes (reliable, deep history), prints ``ready``
once subscribed, records for each message its ``seq`` and the arrival time (``time.perf_counter()``, which on
Linux reads ``CLOCK_MONOTONIC`` and so compares across processes), and when its standard input reaches end of
file prints one JSON object ``{"seq": arrival_s, ...}`` and exits. A watcher in its own process is what a user
runs (``ros2 topic echo``); a subscriber thread in the writer's interpreter would instead measure the GIL's
switch interval (5 ms).
"""

from __future__ import annotations

import json
import sys
import threading
import time
from typing import Any


def main(argv: list[str]) -> int:
    """Listen on the domain ``argv[0]`` until stdin closes; print the arrivals as JSON."""
    from std_msgs.msg import String

    from knic.ros import topics as tp
    from knic.ros.env import ros_context

    domain = int(argv[0])
    received: dict[int, float] = {}
    with ros_context(domain) as context:
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.node import Node

        node = Node("bench_listener", context=context, start_parameter_services=False)

        def take(msg: Any) -> None:
            now = time.perf_counter()
            received[int(json.loads(msg.data)["seq"])] = now

        node.create_subscription(String, tp.FACT_EVENTS, take, tp.reliable(10000))
        executor = SingleThreadedExecutor(context=context)
        executor.add_node(node)
        done = threading.Event()

        def wait_for_eof() -> None:
            sys.stdin.read()
            done.set()

        threading.Thread(target=wait_for_eof, daemon=True).start()
        print("ready", flush=True)
        while not done.is_set():
            executor.spin_once(timeout_sec=0.1)
        node.destroy_node()
    print(json.dumps({str(k): v for k, v in received.items()}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
