"""Limits on what a user hands in: file size, file kind, text encoding, YAML aliases and nesting.

Every reader of a user's file goes through these so that a bad file is one line naming it, never a traceback,
an endless read (``/dev/zero``) or memory blown up by a few hundred bytes (a YAML "billion laughs" file whose
aliases expand exponentially). Errors are raised as the caller's error class (a :class:`KnicError`
subclass) so each boundary keeps its own exit code.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path
from typing import Any

from core.errors import KnicError

#: deepest YAML nesting accepted (world, scenario and sidecar files use fewer than ten levels)
MAX_YAML_DEPTH = 64
#: largest YAML document read (bytes)
MAX_YAML_BYTES = 4 * 1024 * 1024


def check_input_file(path: str | Path, max_bytes: int, what: str, error: type[KnicError] = KnicError) -> Path:
    """``path`` if it is a regular file of at most ``max_bytes`` bytes.

    Raises:
        error: missing, not a regular file (a device such as ``/dev/zero``, a FIFO, a folder) or too large.
    """
    p = Path(path)
    try:
        info = os.stat(p)
    except OSError as exc:
        raise error(f"{p}: cannot read {what} ({exc.strerror or exc})") from None
    if not stat.S_ISREG(info.st_mode):
        raise error(f"{p}: cannot read {what} (not a regular file)")
    if info.st_size > max_bytes:
        raise error(f"{p}: {what} is {info.st_size} bytes, more than the limit of {max_bytes}")
    return p


def read_text_limited(path: str | Path, max_bytes: int, what: str, error: type[KnicError] = KnicError) -> str:
    """The UTF-8 text of a regular file of at most ``max_bytes`` bytes (read no further than the limit).

    Raises:
        error: see :func:`check_input_file`; or the bytes are not UTF-8 (line and byte named).
    """
    p = check_input_file(path, max_bytes, what, error)
    try:
        with p.open("rb") as handle:
            data = handle.read(max_bytes + 1)
    except OSError as exc:
        raise error(f"{p}: cannot read {what} ({exc.strerror or exc})") from None
    if len(data) > max_bytes:
        raise error(f"{p}: {what} is more than the limit of {max_bytes} bytes")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise error(f"{p}:{line}: {what} is not UTF-8 text (byte {exc.start})") from None


def safe_yaml(
    text: str, source: str, error: type[KnicError] = KnicError, max_depth: int = MAX_YAML_DEPTH
) -> Any:
    """Parse one YAML document with the safe loader, refusing aliases and nesting deeper than ``max_depth``.

    Aliases (``*name``) are refused outright: KnIC's files never need them, and they are how a tiny file
    expands to gigabytes.

    Raises:
        error: not valid YAML, an alias, too deep, or more than :data:`MAX_YAML_BYTES` (one line with the line
            number where known).
    """
    import yaml

    if len(text) > MAX_YAML_BYTES:
        raise error(f"{source}: YAML document is more than {MAX_YAML_BYTES} characters")
    try:
        if getattr(yaml, "__with_libyaml__", False):
            # libyaml parses about ten times faster than the pure-Python loader (which is most of a CLI's
            # start-up): one pass over its events checks aliases and depth, a second builds the document.
            _check_events(yaml.parse(text, Loader=yaml.CSafeLoader), source, error, max_depth)
            return yaml.load(text, Loader=yaml.CSafeLoader)
        return yaml.load(text, Loader=_checking_loader(source, error, max_depth))
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f"{source}:{mark.line + 1}" if mark is not None else source
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise error(f"{where}: not valid YAML ({problem})") from None


def _check_events(events: Any, source: str, error: type[KnicError], max_depth: int) -> None:
    """Refuse an alias or nesting deeper than ``max_depth`` in a stream of YAML parser events."""
    import yaml

    too_deep = f"YAML nested deeper than {max_depth} levels"
    depth = 0
    for event in events:
        line = event.start_mark.line + 1
        if isinstance(event, yaml.AliasEvent):
            raise error(f"{source}:{line}: YAML aliases (*name) are not accepted")
        if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
            depth += 1
            if depth > max_depth:
                raise error(f"{source}:{line}: {too_deep}")
        elif isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
            depth -= 1
        elif isinstance(event, yaml.ScalarEvent) and depth + 1 > max_depth:
            raise error(f"{source}:{line}: {too_deep}")


def _checking_loader(source: str, error: type[KnicError], max_depth: int) -> Any:
    """The pure-Python safe loader, refusing aliases and deep nesting as it composes (no libyaml)."""
    import yaml

    class _Loader(yaml.SafeLoader):
        depth = 0

        def compose_node(self, parent: Any, index: Any) -> Any:
            if self.check_event(yaml.AliasEvent):
                mark = self.peek_event().start_mark
                raise error(f"{source}:{mark.line + 1}: YAML aliases (*name) are not accepted")
            self.depth += 1
            if self.depth > max_depth:
                mark = self.peek_event().start_mark
                raise error(f"{source}:{mark.line + 1}: YAML nested deeper than {max_depth} levels")
            try:
                return super().compose_node(parent, index)
            finally:
                self.depth -= 1

    return _Loader


def read_yaml(path: str | Path, what: str, error: type[KnicError] = KnicError) -> Any:
    """Read and parse a user's YAML file: at most :data:`MAX_YAML_BYTES`, UTF-8, no aliases, bounded depth.

    The one reader for every YAML file KnIC takes (worlds, scenarios, roles, language files, noise models,
    voice banks, benchmark sets).

    Raises:
        error: one line naming the file (and the line where known): unreadable, too large, not UTF-8, not
            valid YAML, an alias, or nested too deep.
    """
    text = read_text_limited(path, MAX_YAML_BYTES, what, error)
    return safe_yaml(text, str(path), error)
