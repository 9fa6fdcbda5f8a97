"""sbsim.report's V2X panels (a --messages trace) on motorway-accident runs, and world stories drawn as what
they are (bridge-closure): each figure checked against the data it is drawn from, and that data against
the trace, the FCD and the event log read independently."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from collections import Counter, defaultdict
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from matplotlib.collections import PathCollection
from matplotlib.patches import Rectangle, StepPatch
from sbsim import report
from sbsim.report.compose import Report, build
from sbsim.runner import run
from sbsim_helpers import REPO, STORIES, assert_no_crash

MOTORWAY = STORIES / "motorway-accident"
BRIDGE = STORIES / "bridge-closure"
RANGE = 500.0  # the disc model's default --v2x-range


@dataclass
class V2xRun:
    directory: Path
    lines: list[dict[str, Any]]  # the trace, read line by line here
    report: Report


def _motorway(out: Path, end: float, *extra: str) -> list[dict[str, Any]]:
    result = run(
        MOTORWAY / "motorway.sumocfg",
        story=MOTORWAY / "story.py",
        events=out / "events.jsonl",
        end=end,
        sumo_options=[f"--fcd-output {out / 'fcd.xml'}"],
        extra=[
            "--services",
            str(MOTORWAY / "services.xml"),
            "--messages",
            str(out / "messages.jsonl"),
            "--messages-events",
            "tx,rx,lost,denm",
            *extra,
        ],
        quiet=True,
        timeout=300,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return [json.loads(line) for line in (out / "messages.jsonl").read_text(encoding="utf-8").splitlines()]


@pytest.fixture(scope="module")
def disc(tmp_path_factory: pytest.TempPathFactory) -> V2xRun:
    """The accident at 40 s, its DENM, 60 s in all; the disc radio model (no channel busy ratio)."""
    out = tmp_path_factory.mktemp("v2x-disc")
    lines = _motorway(out, 60.0)
    built = build(
        out / "events.jsonl", MOTORWAY / "motorway.sumocfg", fcd=out / "fcd.xml", messages=out / "messages.jsonl"
    )
    return V2xRun(out, lines, built)


def test_messages_per_type_are_the_trace_transmissions(disc: V2xRun) -> None:
    counted: Counter[tuple[str, float]] = Counter(
        (line["type"], math.floor(line["t"])) for line in disc.lines if line["event"] == "tx"
    )
    table = disc.report.v2x["messages"]
    assert set(table.columns) == {"CAM", "DENM"}
    for (kind, second), n in counted.items():
        assert table.loc[float(second), kind] == n
    assert table.to_numpy().sum() == sum(counted.values())
    # The crash car's DENM, once a second from 40 s, and its GeoNetworking forwards: more frames.
    own = Counter(math.floor(line["t"]) for line in disc.lines if line["event"] == "tx" and line.get("hops") == 1)
    assert table.loc[39.0, "DENM"] == 0 and [own[s] for s in range(40, 60)] == [1] * 20
    assert table.loc[40.0:59.0, "DENM"].sum() > 20
    figure = disc.report.figures["messages"]
    for kind in ("CAM", "DENM"):
        [ax] = [ax for ax in figure.axes if ax.get_label() == kind]
        [stairs] = [p for p in ax.patches if isinstance(p, StepPatch)]
        assert stairs.get_data().values.tolist() == table[kind].tolist()


def test_delivery_ratio_by_distance_bin(disc: V2xRun) -> None:
    received: Counter[tuple[str, int]] = Counter()
    lost: Counter[tuple[str, int]] = Counter()
    for line in disc.lines:
        if line["event"] in ("rx", "lost") and "distance" in line:
            (received if line["event"] == "rx" else lost)[(line["type"], int(line["distance"] // 50))] += 1
    table = disc.report.v2x["delivery"].set_index(["type", "distance"])
    for (kind, k), n in received.items():
        row = table.loc[(kind, 50.0 * k)]
        assert row["received"] == n and row["lost"] == lost[(kind, k)]
        assert row["pdr"] == pytest.approx(n / (n + lost[(kind, k)]))
    # The disc model: every frame within its range arrives, none beyond.
    for kind in ("CAM", "DENM"):
        near = table.loc[kind]
        assert (near.loc[: RANGE - 50, "pdr"] == 1.0).all()
        assert (near.loc[RANGE + 50 :, "pdr"] == 0.0).all() and len(near.loc[RANGE + 50 :]) > 0
    [ax] = disc.report.figures["delivery"].axes
    for line in ax.get_lines():
        rows = table.loc[line.get_label()]
        assert list(line.get_xdata()) == [d + 25.0 for d in rows.index]
        assert list(line.get_ydata()) == rows["pdr"].tolist()


def test_without_a_channel_model_there_is_no_busy_ratio(disc: V2xRun) -> None:
    assert disc.report.v2x["busy_ratio"].empty
    [ax] = disc.report.figures["busy_ratio"].axes
    assert any("--radio" in t.get_text() for t in ax.texts) and not ax.get_lines()


def test_busy_ratio_over_time_with_the_channel_model(tmp_path: Path) -> None:
    # SUMO at 0.1 s, as V2X studies step it: at the scenario's 0.5 s every CA check that sees a vehicle
    # move runs within 100 ms after the step (each station on its own clock), so the 100 ms sample a
    # CAM reports, the one before it, holds no frame.
    lines = _motorway(
        tmp_path, 30.0, "--radio", str(REPO / "bench" / "radio.toml"), "--sumo-option", "--step-length 0.1"
    )
    built = build(
        tmp_path / "events.jsonl", MOTORWAY / "motorway.sumocfg", fcd=None, messages=tmp_path / "messages.jsonl"
    )
    busy = built.v2x["busy_ratio"]
    per_second: defaultdict[int, list[float]] = defaultdict(list)
    for line in lines:
        if line["event"] == "tx" and "cbr" in line:
            per_second[math.floor(line["t"])].append(line["cbr"])
    assert len(per_second) > 20
    for second, values in per_second.items():
        assert busy.loc[float(second), "mean"] == pytest.approx(sum(values) / len(values))
        assert busy.loc[float(second), "max"] == max(values) and busy.loc[float(second), "samples"] == len(values)
    assert busy["max"].max() > 0  # 30 s of CAMs from ~30 cars do load the channel
    [ax] = built.figures["busy_ratio"].axes
    [mean] = [line for line in ax.get_lines() if line.get_label() == "mean"]
    assert list(mean.get_ydata()) == busy["mean"].tolist()
    assert "denm_speeds" not in built.figures  # no FCD given


def test_denm_receivers_slow_down_against_the_others(disc: V2xRun) -> None:
    speeds = disc.report.v2x["denm_speeds"]
    first: dict[str, float] = {}
    for line in disc.lines:
        if line["event"] == "denm" and line["phase"] == "new" and line["station"] != "crash":
            first.setdefault(line["station"], line["t"])
    fcd = report.read_fcd(disc.directory / "fcd.xml")
    at = fcd[fcd["t"] == 55.0]
    warned = at[[first.get(v, math.inf) <= 55.0 for v in at["vehicle"]]]
    others = at.drop(warned.index)
    assert speeds.loc[55.0, "warned_n"] == len(warned) > 10
    assert speeds.loc[55.0, "warned"] == pytest.approx(warned["speed"].mean())
    assert speeds.loc[55.0, "others"] == pytest.approx(others["speed"].mean())
    # The story caps the warned at 15 m/s; the others drive at up to 36 m/s.
    assert speeds.loc[55.0, "warned"] < 16 < 25 < speeds.loc[55.0, "others"]
    assert speeds.loc[:40.0, "warned_n"].sum() == 0  # nobody was warned before the accident
    [ax] = disc.report.figures["denm_speeds"].axes
    [line] = [line for line in ax.get_lines() if line.get_label() == "warned (DENM received)"]
    assert list(line.get_xdata()) == list(speeds.index)


def test_command_writes_the_v2x_panels(disc: V2xRun, tmp_path: Path) -> None:
    page, pngs = tmp_path / "report.html", tmp_path / "png"
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "sbsim.report",
            str(disc.directory / "events.jsonl"),
            "--sumocfg",
            str(MOTORWAY / "motorway.sumocfg"),
            "--fcd",
            str(disc.directory / "fcd.xml"),
            "--messages",
            str(disc.directory / "messages.jsonl"),
            "-o",
            str(page),
            "--png",
            str(pngs),
        ],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    for name in ("messages", "delivery", "busy_ratio", "denm_speeds"):
        assert (pngs / f"{name}.png").read_bytes().startswith(b"\x89PNG")
        assert f'<figure id="{name}">' in page.read_text(encoding="utf-8")
    assert "<h2>Delivery ratio by distance</h2>" in page.read_text(encoding="utf-8")
    bad = subprocess.run(
        [sys.executable, "-m", "sbsim.report", str(disc.directory / "events.jsonl"), "--sumocfg"]
        + [str(MOTORWAY / "motorway.sumocfg"), "--messages", str(disc.directory / "events.jsonl"), "-o", str(page)],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    assert bad.returncode == 2 and len(bad.stderr.strip().splitlines()) == 1, bad.stderr


@pytest.fixture(scope="module")
def bridge(tmp_path_factory: pytest.TempPathFactory) -> Report:
    out = tmp_path_factory.mktemp("bridge")
    result = run(
        BRIDGE / "bridge-closure.sumocfg",
        story=BRIDGE / "story.py",
        events=out / "events.jsonl",
        end=400.0,
        sumo_options=[f"--fcd-output {out / 'fcd.xml'}"],
        quiet=True,
        timeout=300,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return build(out / "events.jsonl", BRIDGE / "bridge-closure.sumocfg", fcd=out / "fcd.xml")


def test_a_world_story_is_a_span_not_a_vehicle(bridge: Report) -> None:
    # bridge-closed, a WorldStory, is active from 120 s to the step after 360 s; detour is per vehicle.
    [ax] = bridge.figures["activity"].axes
    stacked = [p.get_label() for p in ax.patches if isinstance(p, StepPatch)]
    assert stacked == ["detour"]
    [span] = [p for p in ax.patches if p.get_label() == "bridge-closed (world story, active)"]
    assert isinstance(span, Rectangle)  # axvspan's, in data x
    assert (span.get_x(), span.get_x() + span.get_width()) == (120.0, 361.0)


def test_a_world_story_has_no_speed_panel_nor_map_points(bridge: Report) -> None:
    assert [ax.get_label() for ax in bridge.figures["speeds"].axes] == ["detour"]
    [ax] = bridge.figures["map"].axes
    labels = [c.get_label() for c in ax.collections if isinstance(c, PathCollection)]
    assert len(labels) == 1 and labels[0].startswith("detour ("), labels  # no "bridge-closed (0)"
    table = bridge.stories
    assert table.loc["bridge-closed", "kind"] == "world" and math.isnan(table.loc["bridge-closed", "vehicles"])
    assert table.loc["detour", "kind"] == "vehicle" and table.loc["detour", "vehicles"] > 10


def _synthetic_trace(path: Path, lines: int) -> None:
    with open(path, "w", encoding="utf-8") as f:
        for i in range(lines):
            t, station = i * 0.001, f"v{i % 97}"
            if i % 3 == 0:
                line = {
                    "t": t,
                    "event": "tx",
                    "type": "CAM",
                    "station": station,
                    "seq": i,
                    "bytes": 300,
                    "x": 0,
                    "y": 0,
                }
            else:
                line = {"t": t, "event": "rx", "type": "CAM", "station": station, "sender": "v0", "seq": i}
                line["distance"] = float(i % 800)
            f.write(json.dumps(line) + "\n")


def test_the_report_reads_a_trace_in_bounded_memory(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The motorway scenario's own trace is 777 MB: read whole, it ended in MemoryError (issue 29). What the
    # report holds must not grow with the trace: ten times the lines, about the same peak.
    import tracemalloc

    from sbsim import messages
    from sbsim.report.loading import load_messages

    monkeypatch.setattr(messages, "CHUNK_LINES", 1000)
    peaks = {}
    for lines in (3_000, 45_000):
        trace = tmp_path / f"m{lines}.jsonl"
        _synthetic_trace(trace, lines)
        tracemalloc.start()
        tables = load_messages(trace)
        peaks[lines] = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        sent = tables.messages_per_type()
        assert int(sent["CAM"].sum()) == len(range(0, lines, 3))
    assert peaks[45_000] < 1.5 * peaks[3_000], peaks
