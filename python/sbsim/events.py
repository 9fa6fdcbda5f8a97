"""The event log (``sbsim --events FILE``): one JSON object a line, what the stories did and when."""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from typing import Any

__all__ = [
    "EQUIPPED_EVENT_TYPE",
    "EVENT_FIELDS",
    "WORLD_EVENT_TYPES",
    "EventLogError",
    "read_events",
    "read_json_lines",
]


class EventLogError(ValueError):
    """A line of an event log that is not an event: ``path:line: what is wrong``."""

    def __init__(self, path: str | os.PathLike[str], line: int, message: str) -> None:
        super().__init__(f"{os.fspath(path)}:{line}: {message}")
        self.path = os.fspath(path)
        self.line = line


#: What every event carries, whatever its type (sbsim writes them first on each line).
EVENT_FIELDS: dict[str, type | tuple[type, ...]] = {"t": (int, float), "type": str, "story": str, "vehicle": str}
#: Event types a WorldStory writes with ``"vehicle": null`` (it acts on the network, not on a vehicle).
WORLD_EVENT_TYPES = ("activate", "deactivate")
#: The event a vehicle that departs with V2X equipment writes (runs with ``--services`` only), with
#: ``"story": null``: it is no story's.
EQUIPPED_EVENT_TYPE = "equipped"


def read_json_lines(
    path: str | os.PathLike[str], check: Callable[[int, dict[str, Any]], None] | None = None
) -> list[dict[str, Any]]:
    """The JSON objects of a JSON Lines file sbsim wrote, one dict per line (blank lines skipped).

    Raises :class:`EventLogError` (naming the line) for a line that is not a JSON object, and lets
    ``check(line_number, object)`` raise it for an object that lacks what the file's lines carry.
    """
    objects: list[dict[str, Any]] = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, start=1):
            obj = json_line(path, number, line)
            if obj is None:
                continue
            if check is not None:
                check(number, obj)
            objects.append(obj)
    return objects


def json_line(path: str | os.PathLike[str], number: int, line: str) -> dict[str, Any] | None:
    """Line ``number`` of a JSON Lines file as its object; None for a blank line. Raises
    :class:`EventLogError` naming the line for one that is not a JSON object."""
    if not line.strip():
        return None
    try:
        obj = json.loads(line)
    except json.JSONDecodeError as e:
        raise EventLogError(path, number, f"bad JSON: {e.msg} (column {e.colno})") from e
    if not isinstance(obj, dict):
        raise EventLogError(path, number, "not a JSON object")
    return obj


def require_fields(
    path: str | os.PathLike[str], number: int, obj: dict[str, Any], fields: dict[str, type | tuple[type, ...]]
) -> None:
    """Raises :class:`EventLogError` unless ``obj`` has each of ``fields`` with its type (a number is not a bool)."""
    for key, kind in fields.items():
        # bool is an int to isinstance, but never a time or a count.
        if not isinstance(obj.get(key), kind) or isinstance(obj.get(key), bool):
            raise EventLogError(path, number, f"'{key}' missing or not a {_kind_name(kind)}")


def read_events(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    """The events of an ``--events`` file, one dict per line (``pandas.read_json(path, lines=True)`` works too).

    Raises :class:`EventLogError` (naming the line) for a line that is not a JSON object with ``t``,
    ``type``, ``story`` and ``vehicle`` (``None`` in a WorldStory's activate and deactivate lines;
    ``story`` is ``None`` in an ``equipped`` line, a vehicle that departed with V2X equipment);
    blank lines are skipped. A file that cannot be read raises :class:`OSError`, one that is not
    UTF-8 :class:`UnicodeDecodeError`.
    """

    def check(number: int, event: dict[str, Any]) -> None:
        fields = dict(EVENT_FIELDS)
        if event.get("vehicle", 0) is None and event.get("type") in WORLD_EVENT_TYPES:
            del fields["vehicle"]
        if event.get("story", 0) is None and event.get("type") == EQUIPPED_EVENT_TYPE:
            del fields["story"]
        require_fields(path, number, event, fields)

    return read_json_lines(path, check)


def _kind_name(kind: type | tuple[type, ...]) -> str:
    return "number" if isinstance(kind, tuple) else "string"
