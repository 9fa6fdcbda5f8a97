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
    for column in ("t", "event", "type", "station", "sender", "distance", "cbr"):
        if column not in frame:
            frame[column] = pd.Series(dtype="float64" if column in ("t", "distance", "cbr") else "object")
    frame["t"] = frame["t"].astype("float64")
    return frame.reset_index(drop=True)


def messages_per_type(messages: Messages, bin_seconds: float = 1.0) -> pd.DataFrame:
    """Transmissions per message type in each ``bin_seconds`` bin: indexed by the bin's start time (every bin
    from the first to the last transmission), one column per type."""
    frame = messages_frame(messages)
    sent = frame[frame["event"] == "tx"]
    if sent.empty:
        return pd.DataFrame(index=pd.Index([], name="t", dtype="float64"))
    bins = (sent["t"] // bin_seconds) * bin_seconds
    table = pd.crosstab(bins.rename("t"), sent["type"]).astype("int64")
    table.columns.name = None
    first, last = table.index.min(), table.index.max()
    full = [first + k * bin_seconds for k in range(round((last - first) / bin_seconds) + 1)]
    return table.reindex(pd.Index(full, name="t"), fill_value=0)


def delivery_by_distance(messages: Messages, bin_metres: float = DISTANCE_BIN) -> pd.DataFrame:
    """Per message type and distance bin (``distance`` is the bin's lower edge): ``received``, ``lost`` and
    ``pdr`` = received / (received + lost). Bins beyond the farthest lost reception the trace kept are left
    out: past ``--messages-range`` the trace does not say what was lost; a trace with no lost line at all
    (lost receptions are traced only when asked for) gives an empty table."""
    frame = messages_frame(messages)
    heard = frame[frame["event"].isin(["rx", "lost"]) & frame["distance"].notna()]
    if heard.empty:
        return pd.DataFrame(columns=["type", "distance", "received", "lost", "pdr"])
    distance = (heard["distance"].astype("float64") // bin_metres) * bin_metres
    table = (
        pd.crosstab([heard["type"].rename("type"), distance.rename("distance")], heard["event"])
        .reindex(columns=["rx", "lost"], fill_value=0)
        .rename(columns={"rx": "received"})
        .reset_index()
    )
    table.columns.name = None
    kept = heard[heard["event"] == "lost"]["distance"]
    if not len(kept):
        # A trace without lost lines (the default: --messages-events without lost) says nothing of losses.
        return pd.DataFrame(columns=["type", "distance", "received", "lost", "pdr"])
    table = table[table["distance"] <= (kept.max() // bin_metres) * bin_metres]
    table["pdr"] = table["received"] / (table["received"] + table["lost"])
    return table.sort_values(["type", "distance"]).reset_index(drop=True)


def busy_ratio_over_time(messages: Messages, bin_seconds: float = 1.0) -> pd.DataFrame:
    """The channel busy ratio the senders measured, per ``bin_seconds`` bin: ``mean``, ``max`` and ``samples``
    (transmissions carrying one); empty when the trace has none (the disc model)."""
    frame = messages_frame(messages)
    sent = frame[(frame["event"] == "tx") & frame["cbr"].notna()]
    if sent.empty:
        return pd.DataFrame(columns=["mean", "max", "samples"], index=pd.Index([], name="t", dtype="float64"))
    bins = ((sent["t"] // bin_seconds) * bin_seconds).rename("t")
    return (
        sent["cbr"].astype("float64").groupby(bins).agg(["mean", "max", "count"]).rename(columns={"count": "samples"})
    )


def first_denm(messages: Messages) -> pd.Series:
    """When each station first took a DENM in (its DENM memory's first ``denm`` line of phase ``new``;
    a radio reception alone may be one outside the DENM's area, or, with GeoNetworking, a forwarder's
    frame heard beyond it), indexed by station, events a station announced itself left out; a trace
    without ``denm`` lines: its first reception."""
    frame = messages_frame(messages)
    taken = frame[frame["event"] == "denm"]
    if not taken.empty and "phase" in frame and "action" in frame:
        got = taken[taken["phase"] == "new"]
        origin = got["action"].astype(str).str.rsplit(":", n=1).str[0]  # action: "<station>:<sequence>"
        got = got[origin != got["station"]]
    else:
        got = frame[(frame["event"] == "rx") & (frame["type"] == "DENM")]
    return got.groupby("station")["t"].min()


def speeds_by_denm(messages: Messages, fcd: pd.DataFrame) -> pd.DataFrame:
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
