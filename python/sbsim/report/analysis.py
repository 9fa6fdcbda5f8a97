"""What the stories did, from the event log: who was under which story from when to when."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from sbsim.summary import story_figures

#: Events as :func:`sbsim.events.read_events` returns them, or the same as a DataFrame.
Events = Sequence[dict[str, Any]] | pd.DataFrame


def events_frame(events: Events) -> pd.DataFrame:
    """The events as a DataFrame (columns ``t``, ``type``, ``story``, ``vehicle`` at least), in log order."""
    frame = events.copy() if isinstance(events, pd.DataFrame) else pd.DataFrame(list(events))
    for column in ("t", "type", "story", "vehicle"):
        if column not in frame:
            frame[column] = pd.Series(dtype="float64" if column == "t" else "object")
    # Rounded like sbsim's log (1 ms), so times compare equal to the FCD's.
    frame["t"] = frame["t"].astype("float64").round(3)
    return frame.reset_index(drop=True)


def stories(events: Events, summary: Mapping[str, Any] | None = None) -> list[str]:
    """Story names in the order they first appear in the log, then those only the summary lists."""
    # An equipped line is no story's ("story": null).
    names = list(dict.fromkeys(events_frame(events)["story"].dropna()))
    names += [name for name in story_figures(summary) if name not in names]
    return names


def world_stories(events: Events) -> list[str]:
    """The stories whose every line has no vehicle (``"vehicle": null``): WorldStory's, about the network, in
    log order. A story that never activated has no line and is in neither list."""
    frame = events_frame(events)
    named = frame[frame["story"].notna()]
    worldly = named["vehicle"].isna().groupby(named["story"], sort=False).all()
    return [str(name) for name, world in worldly.items() if world]


def stays(events: Events) -> pd.DataFrame:
    """One row per activation: ``story``, ``vehicle``, ``start``, ``end`` (NaN while still active at the
    end of the log), ``duration`` (NaN likewise) and ``reason`` (the deactivation's)."""
    frame = events_frame(events)
    keys = ["story", "vehicle"]
    on = frame[frame["type"] == "activate"][[*keys, "t"]].rename(columns={"t": "start"})
    off = frame[frame["type"] == "deactivate"][[*keys, "t"]].rename(columns={"t": "end"})
    if "reason" in frame:
        off["reason"] = frame.loc[off.index, "reason"]
    else:
        off["reason"] = pd.Series(dtype="object")
    # The n-th deactivation of a story for a vehicle closes its n-th activation.
    # dropna=False: a WorldStory's lines have no vehicle.
    on["n"] = on.groupby(keys, dropna=False).cumcount()
    off["n"] = off.groupby(keys, dropna=False).cumcount()
    out = on.merge(off, on=[*keys, "n"], how="left").drop(columns="n")
    out["duration"] = out["end"] - out["start"]
    return out.reset_index(drop=True)


def active_counts(events: Events, names: Sequence[str] | None = None) -> pd.DataFrame:
    """Vehicles under each story after the evaluation at every time where some count changes: indexed
    by time, one column per story."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame)
    changes = frame[frame["type"].isin(["activate", "deactivate"])]
    delta = changes["type"].map({"activate": 1, "deactivate": -1})
    table = (
        pd.DataFrame({"t": changes["t"], "story": changes["story"], "delta": delta})
        .pivot_table(index="t", columns="story", values="delta", aggfunc="sum", fill_value=0)
        .reindex(columns=names, fill_value=0)
        .cumsum()
    )
    table.columns.name = None
    return table.astype("int64")


def activation_positions(events: Events, fcd: pd.DataFrame) -> pd.DataFrame:
    """Each activation with where its vehicle was (``x``, ``y`` from the FCD at the activation time);
    activations the FCD has no state for are left out."""
    table = stays(events)
    where = fcd[["t", "vehicle", "x", "y"]].rename(columns={"t": "start"})
    return table.merge(where, on=["vehicle", "start"], how="inner")


def speeds_by_story(events: Events, fcd: pd.DataFrame, story: str) -> pd.DataFrame:
    """Mean speed per time step of the running vehicles under ``story`` and of the others: indexed by
    time, columns ``under`` and ``others`` (NaN where a group is empty)."""
    table = stays(events)
    mine = table[table["story"] == story][["vehicle", "start", "end"]]
    rows = fcd[["t", "vehicle"]].reset_index().merge(mine, on="vehicle")
    # Active from its activation's evaluation up to (not including) its deactivation's.
    inside = rows[(rows["t"] >= rows["start"]) & (rows["t"] < rows["end"].fillna(math.inf))]
    under = fcd.index.isin(inside["index"])
    means = fcd.groupby([pd.Series(under, index=fcd.index, name="under"), "t"])["speed"].mean()
    out = pd.DataFrame(index=pd.Index(sorted(fcd["t"].unique()), name="t"))
    out["under"] = means.get(True, pd.Series(dtype="float64")).reindex(out.index)
    out["others"] = means.get(False, pd.Series(dtype="float64")).reindex(out.index)
    return out
