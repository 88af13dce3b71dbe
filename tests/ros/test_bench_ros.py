"""``knic bench ros``'s fact-event figure: every change reaches a subscriber in another process, in order."""

from __future__ import annotations

import pytest

from knic.bench.ros import measure_events


@pytest.mark.timeout(120)
def test_fact_events_reach_a_listener_process_without_loss(domain: int) -> None:
    figures = measure_events(domain, 40, 200.0)
    assert figures["lost_paced"] == 0
    assert figures["lost_burst"] == 0
    assert figures["latency_ms_p50"] is not None and figures["latency_ms_p50"] > 0
