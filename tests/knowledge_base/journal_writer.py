"""Child process for the durability test: writes to a journal forever, printing one ack per returned write.

Usage: python journal_writer.py JOURNAL [BATCH [LIMIT]], JOURNAL made beforehand by the parent (so this
process opens it from the journal alone and starts fast). Each ack line is ``ack <i>`` printed after the write
of object i (the last of a batch of BATCH objects) returned. After LIMIT objects it stops writing and waits;
the parent kills it with SIGKILL long before that.
"""

from __future__ import annotations

import sys
import time

from knowledge_base import KnowledgeBase

ROOMS = ("kitchen", "bedroom", "entrance", "living_room")


def main() -> None:
    batch = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    limit = int(sys.argv[3]) if len(sys.argv) > 3 else 100_000
    kb = KnowledgeBase.from_journal(sys.argv[1])
    print("ready", flush=True)
    i = 0
    while i < limit:
        with kb.batch():
            for _ in range(batch):
                kb.add_instance("item", f"obj{i}", source="writer")
                kb.add_fact("object_at", f"obj{i}", ROOMS[i % 4], source="writer", status="observed")
                i += 1
        print(f"ack {i - 1}", flush=True)
    while True:
        time.sleep(1.0)


if __name__ == "__main__":
    main()
