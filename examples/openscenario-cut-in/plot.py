"""The cut-in example's figure: where Ego and Adversary drive (lateral position, speed, gap) and the
CAMs around them, from a run's FCD output, event log and message trace (see README.md).

    .venv/bin/python examples/openscenario-cut-in/plot.py FCD.xml EVENTS.jsonl MESSAGES.jsonl OUT.png
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd
from sbsim.events import read_events
from sbsim.fcd import read_fcd
from sbsim.messages import read_message_lines

LENGTH = 5.0  # both entities' bounding boxes (cut-in.xosc)


def plot(fcd_path: Path, events_path: Path, messages_path: Path, out: Path) -> None:
    fcd = read_fcd(fcd_path, step=0.1)
    ego = fcd[fcd.vehicle == "Ego"].set_index("t")
    adversary = fcd[fcd.vehicle == "Adversary"].set_index("t")
    events = read_events(events_path)
    window = {
        e["story"].rsplit("/", 1)[-1] + e["type"]: e["t"] for e in events if (e.get("story") or "").startswith("S/A/")
    }
    messages = pd.DataFrame([m for m in read_message_lines(messages_path) if m.get("type") == "CAM"])
    heard = messages[(messages.event == "rx") & (messages.station == "Ego")]

    fig, (lateral, speed, cams) = plt.subplots(3, 1, sharex=True, figsize=(7, 6))
    for name, states in (("Ego", ego), ("Adversary", adversary)):
        lateral.plot(states.index, states.y, label=name)
        speed.plot(states.index, states.speed, label=name)
    both = ego.index.intersection(adversary.index)
    gap = adversary.x[both] - ego.x[both] - LENGTH
    speed.plot(both, gap, color="grey", linestyle=":", label="gap Adversary - Ego (m, freespace)")
    per_second = heard.groupby(heard.t.astype(int))
    cams.bar(
        per_second.size().index + 0.5, per_second.size(), width=0.9, color="lightsteelblue", label="CAMs Ego heard"
    )
    cams.plot(per_second.sender.nunique().index + 0.5, per_second.sender.nunique(), "k.-", label="stations heard")
    for axis in (lateral, speed, cams):
        axis.axvspan(window["CutInactivate"], window["CutIndeactivate"], color="orange", alpha=0.2)
        axis.axvspan(window["Slowactivate"], window["Slowdeactivate"], color="grey", alpha=0.1)
    lateral.set_ylabel("y (m)")
    lateral.legend(loc="upper right")
    lateral.text(window["CutInactivate"], lateral.get_ylim()[1], " CutIn", va="top", color="darkorange")
    lateral.text(window["Slowactivate"], lateral.get_ylim()[1], " Slow", va="top", color="dimgrey")
    speed.set_ylabel("m/s, m")
    speed.legend(loc="lower left", fontsize="small")
    cams.set_ylabel("per second")
    cams.set_xlabel("time (s)")
    cams.legend(loc="upper left", fontsize="small")
    fig.suptitle("cut-in.xosc on the motorway, among SUMO traffic running the CA service")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    plot(*(Path(a) for a in sys.argv[1:]))
