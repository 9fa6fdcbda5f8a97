"""What the radio did, from a run's message trace (``sbsim --messages``): the tables behind the V2X panels.

- :func:`messages_per_type`: transmissions per message type in each time bin (frames: a DENM's
  GeoNetworking forwards count);
- :func:`delivery_by_distance`: packet delivery ratio per message type and 50 m distance bin, from the
  trace's receptions (``rx``) and lost receptions (``lost``; only those the trace keeps, within
  ``--messages-range``, so bins beyond it count receptions only and are left out);
- :func:`busy_ratio_over_time`: the channel busy ratio the senders measured (``cbr`` of ``tx`` lines, the
  802.11p channel model's ``--radio``; the disc model has none), mean and max per time bin;
- :func:`speeds_by_denm`: mean speed per FCD step of the vehicles that had taken a DENM in by then
  against the others.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import pandas as pd

#: Messages as :func:`sbsim.messages.read_messages` returns them, or the same as a DataFrame.
Messages = Sequence[dict[str, Any]] | pd.DataFrame

#: Width of a distance bin of :func:`delivery_by_distance` [m].
DISTANCE_BIN = 50.0


def messages_frame(messages: Messages) -> pd.DataFrame:
    """The trace as a DataFrame with at least ``t``, ``event``, ``type``, ``station``, ``distance``, ``cbr``."""
    frame = messages.copy() if isinstance(messages, pd.DataFrame) else pd.DataFrame(list(messages))
    for column in ("t", "event", "type", "station", "sender", "distance", "cbr", "phase", "action"):
        if column not in frame:
            frame[column] = pd.Series(dtype="float64" if column in ("t", "distance", "cbr") else "object")
    frame["t"] = frame["t"].astype("float64")
    return frame.reset_index(drop=True)


class TraceTables:
    """The V2X panels' data gathered part by part (:meth:`add`, a chunk of the trace at a time), so a trace of
    any length is read in bounded memory: what is kept is counts per bin, type and station, never the lines.
    The tables come out the same whatever the parts."""

    def __init__(self, bin_seconds: float = 1.0, bin_metres: float = DISTANCE_BIN) -> None:
        self.bin_seconds = bin_seconds
        self.bin_metres = bin_metres
        self._sent = pd.Series(dtype="int64")  # by (t bin, type)
        self._heard = pd.Series(dtype="int64")  # by (type, distance bin, event)
        self._farthest_lost: float | None = None
        self._cbr = pd.DataFrame(columns=["sum", "max", "count"], dtype="float64")  # by t bin
        self._first_new = pd.Series(dtype="float64")  # station -> first DENM taken in (phase new)
        self._first_rx = pd.Series(dtype="float64")  # station -> first DENM reception
        self._saw_denm = False

    @classmethod
    def of(cls, messages: Messages, **bins: float) -> TraceTables:
        tables = cls(**bins)
        tables.add(messages)
        return tables

    def add(self, messages: Messages) -> None:
        frame = messages_frame(messages)
        sent = frame[frame["event"] == "tx"]
        if not sent.empty:
            bins = ((sent["t"] // self.bin_seconds) * self.bin_seconds).rename("t")
            counts = sent.groupby([bins, sent["type"].rename("type")]).size()
            self._sent = _summed(self._sent, counts)
            busy = sent[sent["cbr"].notna()]
            if not busy.empty:
                b = ((busy["t"] // self.bin_seconds) * self.bin_seconds).rename("t")
                agg = busy["cbr"].astype("float64").groupby(b).agg(["sum", "max", "count"])
                if self._cbr.empty:
                    self._cbr = agg
                else:
                    both = pd.concat([self._cbr, agg])
                    self._cbr = both.groupby(level=0).agg({"sum": "sum", "max": "max", "count": "sum"})
        heard = frame[frame["event"].isin(["rx", "lost"]) & frame["distance"].notna()]
        if not heard.empty:
            distance = ((heard["distance"].astype("float64") // self.bin_metres) * self.bin_metres).rename("distance")
            counts = heard.groupby([heard["type"].rename("type"), distance, heard["event"].rename("event")]).size()
            self._heard = _summed(self._heard, counts)
            lost = heard[heard["event"] == "lost"]["distance"]
            if len(lost):
                farthest = float(lost.max())
                self._farthest_lost = max(farthest, self._farthest_lost or farthest)
        taken = frame[frame["event"] == "denm"]
        if not taken.empty:
            self._saw_denm = True
            got = taken[taken["phase"] == "new"]
            origin = got["action"].astype(str).str.rsplit(":", n=1).str[0]  # action: "<station>:<sequence>"
            got = got[origin != got["station"]]
            self._first_new = _earliest(self._first_new, got.groupby("station")["t"].min())
        received = frame[(frame["event"] == "rx") & (frame["type"] == "DENM")]
        if not received.empty:
            self._first_rx = _earliest(self._first_rx, received.groupby("station")["t"].min())

    def messages_per_type(self) -> pd.DataFrame:
        """See :func:`messages_per_type`."""
        if self._sent.empty:
            return pd.DataFrame(index=pd.Index([], name="t", dtype="float64"))
        table = self._sent.unstack("type", fill_value=0).astype("int64").sort_index()
        table = table.reindex(columns=sorted(table.columns))
        table.columns.name = None
        first, last = table.index.min(), table.index.max()
        full = [first + k * self.bin_seconds for k in range(round((last - first) / self.bin_seconds) + 1)]
        return table.reindex(pd.Index(full, name="t"), fill_value=0)

    def delivery_by_distance(self) -> pd.DataFrame:
        """See :func:`delivery_by_distance`."""
        empty = pd.DataFrame(columns=["type", "distance", "received", "lost", "pdr"])
        if self._heard.empty or self._farthest_lost is None:
            # A trace without lost lines (the default: --messages-events without lost) says nothing of losses.
            return empty
        table = (
            self._heard.unstack("event", fill_value=0)
            .reindex(columns=["rx", "lost"], fill_value=0)
            .rename(columns={"rx": "received"})
            .reset_index()
        )
        table.columns.name = None
        table = table[table["distance"] <= (self._farthest_lost // self.bin_metres) * self.bin_metres].copy()
        table["received"] = table["received"].astype("int64")
        table["lost"] = table["lost"].astype("int64")
        table["pdr"] = table["received"] / (table["received"] + table["lost"])
        return table.sort_values(["type", "distance"]).reset_index(drop=True)

    def busy_ratio_over_time(self) -> pd.DataFrame:
        """See :func:`busy_ratio_over_time`."""
        if self._cbr.empty:
            return pd.DataFrame(columns=["mean", "max", "samples"], index=pd.Index([], name="t", dtype="float64"))
        table = self._cbr.sort_index()
        out = pd.DataFrame(
            {"mean": table["sum"] / table["count"], "max": table["max"], "samples": table["count"].astype("int64")},
            index=table.index,
        )
        out.index.name = "t"
        return out

    def first_denm(self) -> pd.Series:
        """See :func:`first_denm`."""
        first = self._first_new if self._saw_denm else self._first_rx
        return first.rename("t").rename_axis("station").sort_index()


def _summed(kept: pd.Series, more: pd.Series) -> pd.Series:
    """Counts added up per index."""
    return more.astype("int64") if kept.empty else kept.add(more, fill_value=0).astype("int64")


def _earliest(kept: pd.Series, more: pd.Series) -> pd.Series:
    """Per index, the smaller of the two (an index in one only: its value)."""
    if kept.empty:
        return more.astype("float64")
    return pd.concat([kept, more.astype("float64")]).groupby(level=0).min()


def messages_per_type(messages: Messages, bin_seconds: float = 1.0) -> pd.DataFrame:
    """Transmissions per message type in each ``bin_seconds`` bin: indexed by the bin's start time (every bin
    from the first to the last transmission), one column per type."""
    return TraceTables.of(messages, bin_seconds=bin_seconds).messages_per_type()


def delivery_by_distance(messages: Messages, bin_metres: float = DISTANCE_BIN) -> pd.DataFrame:
    """Per message type and distance bin (``distance`` is the bin's lower edge): ``received``, ``lost`` and
    ``pdr`` = received / (received + lost). Bins beyond the farthest lost reception the trace kept are left
    out: past ``--messages-range`` the trace does not say what was lost; a trace with no lost line at all
    (lost receptions are traced only when asked for) gives an empty table."""
    return TraceTables.of(messages, bin_metres=bin_metres).delivery_by_distance()


def busy_ratio_over_time(messages: Messages, bin_seconds: float = 1.0) -> pd.DataFrame:
    """The channel busy ratio the senders measured, per ``bin_seconds`` bin: ``mean``, ``max`` and ``samples``
    (transmissions carrying one); empty when the trace has none (the disc model)."""
    return TraceTables.of(messages, bin_seconds=bin_seconds).busy_ratio_over_time()


def first_denm(messages: Messages | TraceTables) -> pd.Series:
    """When each station first took a DENM in (its DENM memory's first ``denm`` line of phase ``new``;
    a radio reception alone may be one outside the DENM's area, or, with GeoNetworking, a forwarder's
    frame heard beyond it), indexed by station, events a station announced itself left out; a trace
    without ``denm`` lines: its first reception."""
    tables = messages if isinstance(messages, TraceTables) else TraceTables.of(messages)
    return tables.first_denm()


def speeds_by_denm(messages: Messages | TraceTables, fcd: pd.DataFrame) -> pd.DataFrame:
    """Mean speed per FCD step of the running vehicles that had taken a DENM in at or before that step
    (``warned``) and of the others (``others``), indexed by time (NaN where a group is empty); ``warned_n``
    and ``others_n`` count them."""
    first = first_denm(messages)
    since = fcd["vehicle"].map(first).astype("float64").fillna(math.inf)
    warned = pd.Series(fcd["t"].to_numpy() >= since.to_numpy(), index=fcd.index, name="warned")
    grouped = fcd.groupby([warned, fcd["t"]])["speed"].agg(["mean", "count"])
    out = pd.DataFrame(index=pd.Index(sorted(fcd["t"].unique()), name="t"))
    for flag, name in ((True, "warned"), (False, "others")):
        part = grouped.xs(flag, level="warned") if flag in grouped.index.get_level_values("warned") else None
        out[name] = part["mean"].reindex(out.index) if part is not None else math.nan
        out[f"{name}_n"] = part["count"].reindex(out.index).fillna(0).astype("int64") if part is not None else 0
    return out
