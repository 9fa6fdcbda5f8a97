"""The message trace (``sbsim --messages FILE``): one JSON object a line, in time order, what the radio did:
``tx`` per transmission, ``rx`` per reception, ``lost`` per lost reception within the radio's trace range."""

from __future__ import annotations

import os
from typing import Any

from sbsim.events import EventLogError, read_json_lines, require_fields

__all__ = ["MESSAGE_FIELDS", "read_messages"]

#: What each kind of line carries at least (extra fields may follow: power, SINR, a DENM's cause, ...;
#: ``tx`` lines of sbsim since frames have their real size also carry ``frame_bytes``, the whole 802.11
#: frame around ``bytes``, not required here so that older traces still read).
MESSAGE_FIELDS: dict[str, dict[str, type | tuple[type, ...]]] = {
    "tx": {
        "t": (int, float),
        "type": str,
        "station": str,
        "seq": int,
        "bytes": int,
        "x": (int, float),
        "y": (int, float),
    },
    "rx": {"t": (int, float), "type": str, "station": str, "sender": str, "seq": int, "distance": (int, float)},
    "lost": {"t": (int, float), "type": str, "station": str, "sender": str, "seq": int, "reason": str},
}


def read_messages(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    """The lines of a ``--messages`` trace, one dict per line, in time order: ``tx`` per transmission,
    ``rx`` per reception, ``lost`` per lost reception within the radio's trace range (``reason``:
    sensing, propagation, collision, half-duplex, queue; the disc model: range, fade). Lines of other
    events (a DENM's ``denm`` phase lines) are kept as they are.

    Raises :class:`EventLogError` (naming the line) for a line that is not such an object.
    """

    def check(number: int, line: dict[str, Any]) -> None:
        event = line.get("event")
        if not isinstance(event, str):
            raise EventLogError(path, number, "not a message trace line (no 'event')")
        if event in MESSAGE_FIELDS:
            require_fields(path, number, line, MESSAGE_FIELDS[event])

    return read_json_lines(path, check)
