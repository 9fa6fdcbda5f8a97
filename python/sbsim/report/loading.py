"""Reading one run's files for the report, every failure turned into a :class:`ReportError` naming the file."""

from __future__ import annotations

import os
import xml.sax
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

import pandas as pd
import sumolib

from sbsim.events import EventLogError, read_events
from sbsim.fcd import FcdError, read_fcd
from sbsim.messages import iter_messages
from sbsim.report.v2x import TraceTables
from sbsim.summary import SummaryError, read_summary

_T = TypeVar("_T")


class ReportError(ValueError):
    """An input the report cannot use (one line naming the file)."""


def _unreadable(path: str | os.PathLike[str], e: OSError) -> ReportError:
    return ReportError(f"{path}: {e.strerror or e}")


@dataclass(frozen=True)
class Scenario:
    """What the report reads from a sumocfg: its net file and step length."""

    sumocfg: Path
    net_file: Path
    step_length: float | None


def read_sumocfg(path: str | os.PathLike[str]) -> Scenario:
    """The sumocfg's ``net-file`` (relative to the sumocfg) and ``step-length`` (None if not set)."""
    path = Path(path)
    # sax would take a missing path for a URL and fail with a confusing message.
    if not path.is_file():
        raise ReportError(f"{path}: No such file" if not path.exists() else f"{path}: not a file")
    try:
        options = {o.name: o.value for o in sumolib.options.readOptions(os.fspath(path))}
    except OSError as e:
        raise _unreadable(path, e) from e
    except xml.sax.SAXParseException as e:
        raise ReportError(f"{path}:{e.getLineNumber()}: bad XML: {e.getMessage()}") from e
    except (xml.sax.SAXException, UnicodeDecodeError) as e:
        raise ReportError(f"{path}: bad XML: {e}") from e
    net = options.get("net-file", "").split(",")[0].strip()
    if not net:
        raise ReportError(f"{path}: names no net-file")
    try:
        step = float(options["step-length"]) if "step-length" in options else None
    except ValueError as e:
        raise ReportError(f"{path}: step-length is not a number") from e
    return Scenario(path, path.parent / net, step)


def read_net(path: str | os.PathLike[str]) -> sumolib.net.Net:
    """The SUMO network (sumolib)."""
    if not Path(path).is_file():
        raise ReportError(f"{path}: no such net file" if not Path(path).exists() else f"{path}: not a file")
    try:
        return sumolib.net.readNet(os.fspath(path))
    except OSError as e:
        raise _unreadable(path, e) from e
    except xml.sax.SAXParseException as e:
        raise ReportError(f"{path}:{e.getLineNumber()}: bad XML: {e.getMessage()}") from e
    except (xml.sax.SAXException, UnicodeDecodeError, ValueError, KeyError) as e:
        raise ReportError(f"{path}: not a SUMO network ({e})") from e


def load_summary(path: str | os.PathLike[str]) -> dict[str, Any]:
    """The run's ``--summary`` JSON (:func:`sbsim.summary.read_summary`)."""
    try:
        return read_summary(path)
    except OSError as e:
        raise _unreadable(path, e) from e
    except SummaryError as e:
        raise ReportError(str(e)) from e


def _load_lines(path: str | os.PathLike[str], read: Callable[[str | os.PathLike[str]], _T]) -> _T:
    """A JSON Lines file read by `read`, its failures as one-line ReportErrors."""
    try:
        return read(path)
    except EventLogError as e:
        raise ReportError(str(e)) from e
    except OSError as e:
        raise _unreadable(path, e) from e
    except UnicodeDecodeError as e:
        raise ReportError(f"{path}: not UTF-8 text") from e


def load_events(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    """The run's event log (:func:`sbsim.events.read_events`)."""
    return _load_lines(path, read_events)


def load_fcd(path: str | os.PathLike[str], fallback_step: float = 1.0) -> pd.DataFrame:
    """The run's FCD output as a table (:func:`sbsim.fcd.read_fcd`)."""
    try:
        return read_fcd(path, fallback_step=fallback_step)
    except OSError as e:
        raise _unreadable(path, e) from e
    except FcdError as e:
        raise ReportError(str(e)) from e


#: The trace's columns the V2X panels read (:mod:`sbsim.report.v2x`).
MESSAGE_COLUMNS = ("t", "event", "type", "station", "sender", "distance", "cbr", "phase", "action")


def load_messages(path: str | os.PathLike[str]) -> TraceTables:
    """The V2X panels' data from the run's message trace (JSON Lines or Parquet), read a part at a time
    (:func:`sbsim.messages.iter_messages`) and gathered into counts (:class:`~sbsim.report.v2x.TraceTables`),
    so memory stays bounded whatever the trace's length (a motorway run's trace is hundreds of MB)."""

    def gather(p: str | os.PathLike[str]) -> TraceTables:
        tables = TraceTables()
        for part in iter_messages(p, MESSAGE_COLUMNS):
            tables.add(part)
        return tables

    return _load_lines(path, gather)
