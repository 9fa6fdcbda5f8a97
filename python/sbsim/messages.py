"""The message trace (``sbsim --messages FILE``), in time order, what the radio did: ``tx`` per transmission,
``rx`` per reception, ``lost`` per lost reception (when asked for: ``--messages-events ...,lost`` or
``--messages-range``), and ``denm`` per DENM phase. JSON Lines (one object a line), or Parquet for
``FILE.parquet`` (the same fields as columns, ``t`` in seconds; a study keeps one Parquet dataset of its runs'
traces, partitioned by ``run``).

:func:`read_messages` reads either as a pandas DataFrame, only the columns and rows asked for, so memory
follows the table, not the file; :func:`read_message_lines` gives a JSON Lines trace's lines as dicts.
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from sbsim.events import EventLogError, json_line, read_json_lines, require_fields

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["MESSAGE_FIELDS", "MessageTraceError", "Filters", "iter_messages", "read_message_lines", "read_messages"]

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

#: Row filters as pyarrow takes them: ``[("event", "==", "rx"), ("t", ">=", 10)]`` (all must hold), or a list
#: of such lists (any may hold). Operators: ``==`` (``=``), ``!=``, ``<``, ``<=``, ``>``, ``>=``, ``in``,
#: ``not in``. A line without the column matches none of them.
Filters = Sequence[tuple[str, str, Any]] | Sequence[Sequence[tuple[str, str, Any]]]

#: Lines of a JSON Lines trace parsed at a time: what memory holds beyond the table being built.
CHUNK_LINES = 100_000

_OPERATORS = ("==", "=", "!=", "<", "<=", ">", ">=", "in", "not in")


class MessageTraceError(EventLogError):
    """A message trace that cannot be read as one: ``path: what is wrong`` (``path:line: ...`` for a line)."""

    def __init__(self, path: str | os.PathLike[str], message: str, line: int = 0) -> None:
        ValueError.__init__(self, f"{os.fspath(path)}:{line}: {message}" if line else f"{os.fspath(path)}: {message}")
        self.path = os.fspath(path)
        self.line = line


def _check_line(path: str | os.PathLike[str], number: int, line: dict[str, Any]) -> None:
    event = line.get("event")
    if not isinstance(event, str):
        raise EventLogError(path, number, "not a message trace line (no 'event')")
    if event in MESSAGE_FIELDS:
        require_fields(path, number, line, MESSAGE_FIELDS[event])


def read_message_lines(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    """The lines of a JSON Lines ``--messages`` trace, one dict per line, in time order (the whole file in
    memory: for small traces; :func:`read_messages` reads large ones). Lines of other events (a DENM's
    ``denm`` phase lines) are kept as they are.

    Raises :class:`EventLogError` (naming the line) for a line that is not such an object.
    """
    return read_json_lines(path, lambda number, line: _check_line(path, number, line))


def is_parquet(path: str | os.PathLike[str]) -> bool:
    """A Parquet file (by its magic bytes, whatever its name) or a folder (a Parquet dataset)."""
    p = Path(path)
    if p.is_dir():
        return True
    with open(p, "rb") as f:
        return f.read(4) == b"PAR1"


def read_messages(
    path: str | os.PathLike[str], columns: Sequence[str] | None = None, filters: Filters | None = None
) -> pd.DataFrame:
    """A ``--messages`` trace as a DataFrame, a row per line in time order (``t`` in seconds; a field a line
    lacks is null): only ``columns`` (default: all; one the trace lacks comes back all null) of the rows that
    pass ``filters`` (see :data:`Filters`), e.g. the DENM receptions' times and stations::

        read_messages("m.parquet", columns=["t", "station"], filters=[("event", "==", "rx"), ("type", "==", "DENM")])

    Parquet (a file, or a folder: a dataset such as a study's ``messages/``, whose partition ``run`` becomes a
    column) is read by pyarrow, only the columns asked for and skipping row groups the filters rule out.
    JSON Lines is read in chunks of :data:`CHUNK_LINES` lines, each checked as :func:`read_message_lines`
    checks them, filtered and cut to the columns before the next is read.

    Raises :class:`EventLogError` (naming the line) for a JSON Lines line that is not a trace line, and
    :class:`MessageTraceError` for a Parquet file pyarrow cannot read or filters it cannot apply.
    """
    clauses = _clauses(path, filters)
    if is_parquet(path):
        return _read_parquet(path, columns, filters)
    return _read_json_lines(path, columns, clauses)


def iter_messages(path: str | os.PathLike[str], columns: Sequence[str]) -> Iterator[pd.DataFrame]:
    """A ``--messages`` trace as consecutive DataFrames of ``columns`` (one the trace lacks comes back all null),
    together all its rows in order, for a reader that aggregates as it goes: memory holds one part at a time
    (:data:`CHUNK_LINES` lines of JSON Lines, a record batch of Parquet), whatever the trace's length.

    Raises as :func:`read_messages` does."""
    import pandas as pd

    wanted = list(columns)
    if is_parquet(path):
        import pyarrow as pa
        import pyarrow.dataset as ds

        try:
            dataset = ds.dataset(os.fspath(path), format="parquet", partitioning="hive")
            present = [c for c in wanted if c in dataset.schema.names]
            for batch in dataset.to_batches(columns=present, batch_size=CHUNK_LINES):
                yield batch.to_pandas().reindex(columns=wanted)
        except (pa.ArrowException, ValueError, TypeError, KeyError) as e:
            raise MessageTraceError(path, f"not a readable message trace: {e}") from e
        return
    needed = set(wanted)
    for _, objects in _chunks(path):
        yield pd.DataFrame.from_records(
            [{k: v for k, v in obj.items() if k in needed} for obj in objects], columns=wanted
        )


def _clauses(path: str | os.PathLike[str], filters: Filters | None) -> list[list[tuple[str, str, Any]]]:
    """Filters as a list of alternatives, each a list of (column, operator, value)."""
    if not filters:
        return []
    first = filters[0]
    alternatives = [list(f) for f in filters] if isinstance(first, list) else [list(filters)]  # type: ignore[arg-type]
    for clause in itertools.chain.from_iterable(alternatives):
        if not (isinstance(clause, tuple) and len(clause) == 3 and clause[1] in _OPERATORS):
            raise MessageTraceError(path, f"bad filter {clause!r}: expected (column, operator, value)")
    return alternatives


def _read_parquet(path: str | os.PathLike[str], columns: Sequence[str] | None, filters: Filters | None) -> pd.DataFrame:
    import pyarrow as pa
    import pyarrow.dataset as ds

    try:
        dataset = ds.dataset(os.fspath(path), format="parquet", partitioning="hive")
        names = dataset.schema.names
        wanted = list(names if columns is None else columns)
        present = [c for c in wanted if c in names]
        expression = _expression(filters) if filters else None
        table = dataset.to_table(columns=present, filter=expression)
    except (pa.ArrowException, ValueError, TypeError, KeyError) as e:
        raise MessageTraceError(path, f"not a readable message trace: {e}") from e
    frame = table.to_pandas()
    for c in wanted:
        if c not in frame:
            frame[c] = None
    return frame[wanted]


def _expression(filters: Filters) -> Any:
    import pyarrow.compute as pc

    def one(column: str, op: str, value: Any) -> Any:
        field = pc.field(column)
        if op in ("==", "="):
            return field == value
        if op == "!=":
            return field != value
        if op == "<":
            return field < value
        if op == "<=":
            return field <= value
        if op == ">":
            return field > value
        if op == ">=":
            return field >= value
        if op == "in":
            return field.isin(list(value))
        return ~field.isin(list(value))

    alternatives = _clauses("", filters)
    result = None
    for clauses in alternatives:
        conjunction = None
        for column, op, value in clauses:
            term = one(column, op, value)
            conjunction = term if conjunction is None else conjunction & term
        result = conjunction if result is None else result | conjunction
    return result


def _chunks(path: str | os.PathLike[str]) -> Iterator[tuple[int, list[dict[str, Any]]]]:
    """(first line number, the chunk's objects), every object checked."""
    with open(path, encoding="utf-8") as f:
        number = 0
        while True:
            lines = list(itertools.islice(f, CHUNK_LINES))
            if not lines:
                return
            first = number + 1
            objects = []
            for text in lines:
                number += 1
                obj = json_line(path, number, text)
                if obj is None:
                    continue
                _check_line(path, number, obj)
                objects.append(obj)
            yield first, objects


def _read_json_lines(
    path: str | os.PathLike[str], columns: Sequence[str] | None, clauses: list[list[tuple[str, str, Any]]]
) -> pd.DataFrame:
    import pandas as pd

    needed = None if columns is None else set(columns) | {c for alt in clauses for c, _, _ in alt}
    parts: list[pd.DataFrame] = []
    seen: dict[str, None] = {}
    for _, objects in _chunks(path):
        if needed is not None:
            objects = [{k: v for k, v in obj.items() if k in needed} for obj in objects]
        for obj in objects:
            seen.update(dict.fromkeys(obj))
        frame = pd.DataFrame.from_records(objects)
        if clauses:
            frame = frame[_mask(frame, clauses)]
        if columns is not None:
            frame = frame.reindex(columns=list(columns))
        parts.append(frame.reset_index(drop=True))
    wanted = list(columns) if columns is not None else list(seen)
    if not parts:
        return pd.DataFrame(columns=wanted)
    return pd.concat(parts, ignore_index=True).reindex(columns=wanted)


def _mask(frame: pd.DataFrame, clauses: list[list[tuple[str, str, Any]]]) -> Any:
    import pandas as pd

    def one(column: str, op: str, value: Any) -> pd.Series:
        if column not in frame:
            return pd.Series(False, index=frame.index)
        values = frame[column]
        present = values.notna()
        if op in ("==", "="):
            hit = values == value
        elif op == "!=":
            hit = values != value
        elif op in ("in", "not in"):
            hit = values.isin(list(value))
            hit = ~hit if op == "not in" else hit
        else:
            numbers = pd.to_numeric(values, errors="coerce")
            hit = {"<": numbers < value, "<=": numbers <= value, ">": numbers > value, ">=": numbers >= value}[op]
        return hit.fillna(False).astype(bool) & present

    result = pd.Series(False, index=frame.index)
    for alternative in clauses:
        conjunction = pd.Series(True, index=frame.index)
        for column, op, value in alternative:
            conjunction &= one(column, op, value)
        result |= conjunction
    return result
