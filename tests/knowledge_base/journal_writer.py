"""Child process for the durability test: writes to a journal forever, printing one ack per returned write.

Usage: python journal_writer.py JOURNAL [BATCH]. Each ack line is ``ack <i>`` printed after the i-th write
(or batch of BATCH writes) returned; the parent kills this process with SIGKILL at some point.
"""

from __future__ import annotations

import sys
from pathlib import Path

from knowledge_base import KnowledgeBase

ROOMS = ("kitchen", "bedroom", "entrance", "living_room")


def main() -> None:
    repo = Path(__file__).resolve().parents[2]
    erl = repo / "worlds" / "erl_home"
    batch = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    kb = KnowledgeBase.from_pddl(erl / "domain.pddl", erl / "paper_problem.pddl", sys.argv[1])
    print("ready", flush=True)
    i = 0
    while True:
        with kb.batch():
            for _ in range(batch):
                kb.add_instance("item", f"obj{i}", source="writer")
                kb.add_fact("object_at", f"obj{i}", ROOMS[i % 4], source="writer", status="observed")
                i += 1
        print(f"ack {i - 1}", flush=True)


if __name__ == "__main__":
    main()
