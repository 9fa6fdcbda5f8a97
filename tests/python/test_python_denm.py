"""DENMs from Python services (`Service.send_denm` / `terminate_denm`): sent through the DEN service's own sender
(action ids, repetition, geo-broadcast, cancellation), so a Python roadside unit's event is the C++
RsuDenService's byte for byte in the trace, receivers' DenmCondition stories see it, its cancellation drops it from
their DENM memory, and bad arguments are exit 2 naming the service, station, time, file and line."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pandas as pd
from sbsim.messages import read_message_lines
from sbsim.runner import RunResult, read_events, run
from sbsim_helpers import assert_bad_input, assert_no_crash, services_file, write_file, write_story

#: RsuDenService cause="3" from="10" until="60" area="150" validity="100" (interval 1 s), in Python: repeated
#: until the event ends at 60 s, valid for 100 s (so receivers drop it at 60 s for the cancellation, not expiry).
ANNOUNCER = """
import math

from storyboard.services import Service


class Roadworks(Service):
    sends_denms = True
    attributes = {"area": float}

    def initialize(self) -> None:
        self.schedule_after(10.0, self.start)

    def start(self) -> None:
        area = self.attribute("area", 150.0)
        self.action = self.send_denm(cause=3, subcause=0, area=area, validity=100.0, repetition=50.0)
        self.record_scalar("sequence", int(self.action.split(":")[1]))
        self.schedule_after(50.0, self.end)

    def end(self) -> None:
        self.record_scalar("terminated", self.terminate_denm(self.action))
        self.record_scalar("again", self.terminate_denm(self.action))  # ended already: nothing sent


class Watcher(Service):
    \"\"\"Emits, every trigger, how many roadworks events its DENM memory holds, and each DENM it is handed.\"\"\"

    def trigger(self) -> None:
        self.emit("held", sum(1 for d in self.denms if d.cause == 3))

    def on_denm(self, denm) -> None:
        self.emit("terminated" if denm.terminated else "heard", denm.detection_time)
        self.emit("distance", math.dist(self.position, denm.event_position))


class Undeclared(Service):
    def initialize(self) -> None:
        self.schedule_after(5.0, self.go)

    def go(self) -> None:
        self.send_denm(cause=3)


class BadCause(Service):
    sends_denms = True

    def trigger(self) -> None:
        if self.time > 5 and self.station_id == "veh03":
            self.send_denm(cause=300, area=100)  # the user's bug


class NotBool(Service):
    sends_denms = "yes"
"""

#: Vehicles whose DENM memory holds the roadworks event are capped at 5 m/s.
DENM_STORY = """
from storyboard import DenmCondition, SpeedEffect, Story

def createStories(board):
    board.registerStory(Story(DenmCondition(cause=3), [SpeedEffect(5.0)], name="warned"))
"""

UNIT = (300.0, 300.0)


def run_ok(cfg: Path, *extra: str, story: Path | None = None, events: Path | None = None) -> RunResult:
    result = run(cfg, story=story, events=events, end=80.0, seed=7, extra=list(extra), timeout=300)
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return result


def test_a_python_units_denm_is_rsu_den_services_byte_for_byte_with_any_threads(
    loops_cfg: Path, tmp_path: Path
) -> None:
    write_file(tmp_path, "den.py", ANNOUNCER)
    unit = f'<rsu id="rsu0" x="{UNIT[0]:g}" y="{UNIT[1]:g}">{{}}</rsu>'
    cpp = services_file(
        tmp_path,
        '<service type="CaService"/>',
        unit.format('<service type="RsuDenService" cause="3" from="10" until="60" area="150" validity="100"/>'),
        name="cpp.xml",
    )
    py = services_file(
        tmp_path, '<service type="CaService"/>', unit.format('<service type="python:den.py:Roadworks" area="150"/>')
    )
    traces = {}
    for name, services, threads in (("cpp", cpp, "1"), ("py", py, "1"), ("py2", py, "2")):
        trace = tmp_path / f"{name}.jsonl"
        run_ok(loops_cfg, "--services", str(services), "--messages", str(trace), "--threads", threads)
        traces[name] = trace.read_bytes()
    assert traces["cpp"] == traces["py"] == traces["py2"]
    lines = read_message_lines(tmp_path / "py.jsonl")
    sent = [line for line in lines if line["event"] == "tx" and line["type"] == "DENM" and line["station"] == "rsu0"]
    # Every second from 10 s while less than 50 s passed, then the cancellation at 60 s (a smaller DENM:
    # the management container only), each with the event's cause, subcause and action id.
    assert [line["t"] for line in sent] == [float(t) for t in range(10, 60)] + [60.0]
    assert {(line["station"], line["cause"], line["subcause"], line["action"]) for line in sent} == {
        ("rsu0", 3, 0, "rsu0:1")
    }
    assert len({line["bytes"] for line in sent[:-1]}) == 1 and sent[-1]["bytes"] < sent[0]["bytes"]
    # Vehicles in the area forward it (GeoNetworking), as they do the C++ unit's: the same lines.
    assert any(line["event"] == "tx" and line["type"] == "DENM" and line["station"] != "rsu0" for line in lines)
    phases = Counter((line["station"] == "rsu0", line["phase"]) for line in lines if line["event"] == "denm")
    assert phases[True, "new"] == phases[True, "terminate"] == 1
    assert phases[False, "new"] > 3 and phases[False, "terminate"] > 0


def test_a_python_denm_reaches_denm_condition_stories_and_its_end_drops_it(loops_cfg: Path, tmp_path: Path) -> None:
    write_file(tmp_path, "den.py", ANNOUNCER)
    story = write_story(tmp_path, DENM_STORY)
    services = services_file(
        tmp_path,
        '<service type="python:den.py:Watcher"/>',
        f'<rsu id="rsu0" x="{UNIT[0]:g}" y="{UNIT[1]:g}"><service type="python:den.py:Roadworks"/></rsu>',
    )
    trace, stats, events = tmp_path / "trace.jsonl", tmp_path / "stats.parquet", tmp_path / "events.jsonl"
    run_ok(
        loops_cfg,
        "--services",
        str(services),
        "--messages",
        str(trace),
        "--statistics",
        str(stats),
        story=story,
        events=events,
    )
    table = pd.read_parquet(stats)
    unit = table[table["vehicle"] == "rsu0"].set_index("name")["value"]
    assert unit["sequence"] == 1 and unit["terminated"] == 1 and unit["again"] == 0
    lines = read_message_lines(trace)
    denm = [line for line in lines if line["event"] == "denm" and line["station"] != "rsu0"]
    heard = {line["station"]: line["t"] for line in denm if line["phase"] == "new"}
    dropped = {line["station"]: line["t"] for line in denm if line["phase"] == "terminate"}
    assert len(heard) > 3 and dropped and set(dropped) <= set(heard)
    # Only stations inside the 150 m circle take the geo-broadcast (where they were at the step's positions).
    distances = table[table["name"] == "distance"]["value"]
    assert len(distances) > 0 and distances.max() <= 150 + 1e-6
    # The story activates for exactly the vehicles whose DENM memory took the event.
    log = read_events(events)
    warned = {e["vehicle"] for e in log if e["story"] == "warned" and e["type"] == "activate"}
    assert warned == set(heard)
    # The Python services saw the same: on_denm for the event and for its cancellation; the memory held it
    # from the first DENM on (nothing before 10 s) and, where the cancellation reached, no longer after it.
    rows = table[table["vehicle"] != "rsu0"]
    assert set(rows[rows["name"] == "heard"]["vehicle"]) == set(heard)
    # (on_denm gets a cancellation in the area even where the memory never kept the event: a superset)
    assert set(dropped) <= set(rows[rows["name"] == "terminated"]["vehicle"])
    held = rows[rows["name"] == "held"]
    assert held[held["time"] < 10]["value"].eq(0).all() and held["value"].isin([0, 1]).all()
    for station, t in dropped.items():
        mine = held[held["vehicle"] == station]
        assert mine[(mine["time"] > heard[station]) & (mine["time"] < t)]["value"].eq(1).all()
        assert mine[mine["time"] > t]["value"].eq(0).all() and (mine["time"] > t).any()


def test_send_denm_needs_sends_denms(loops_cfg: Path, tmp_path: Path) -> None:
    source = write_file(tmp_path, "den.py", ANNOUNCER)
    services = services_file(
        tmp_path, '<rsu id="rsu0" x="300" y="300"><service type="python:den.py:Undeclared"/></rsu>'
    )
    result = run(loops_cfg, end=20.0, seed=7, extra=["--services", str(services)], timeout=120)
    assert_no_crash(result)
    assert result.returncode == 2, result.stderr
    last = result.stderr.splitlines()[-1]
    line = next(n for n, text in enumerate(source.read_text().splitlines(), 1) if "self.send_denm(cause=3)" in text)
    for needle in ("python:den.py:Undeclared", "rsu0", "at t=5", f"{source}:{line}", "sends_denms = True"):
        assert needle in last, (needle, last)


def test_bad_send_denm_arguments_are_exit_2_naming_service_station_time_file_and_line(
    loops_cfg: Path, tmp_path: Path
) -> None:
    source = write_file(tmp_path, "den.py", ANNOUNCER)
    services = services_file(tmp_path, '<service type="python:den.py:BadCause"/>')
    result = run(loops_cfg, end=20.0, seed=7, extra=["--services", str(services)], timeout=120)
    assert_no_crash(result)
    assert result.returncode == 2, result.stderr
    last = result.stderr.splitlines()[-1]
    line = next(n for n, text in enumerate(source.read_text().splitlines(), 1) if "the user's bug" in text)
    for needle in ("python:den.py:BadCause", "vehicle veh03", "at t=5.", f"{source}:{line}", "cause must be"):
        assert needle in last, (needle, last)


def test_sends_denms_must_be_a_bool(loops_cfg: Path, tmp_path: Path) -> None:
    write_file(tmp_path, "den.py", ANNOUNCER)
    services = services_file(tmp_path, '<service type="python:den.py:NotBool"/>')
    for extra in (["check"], []):
        result = run(loops_cfg, end=5.0, extra=[*extra, "--services", str(services)], timeout=120)
        assert_bad_input(result, f"{services}:2:", "NotBool.sends_denms must be True or False")


def test_a_python_services_file_is_an_input_no_output_may_overwrite(loops_cfg: Path, tmp_path: Path) -> None:
    source = write_file(tmp_path, "den.py", ANNOUNCER)
    services = services_file(tmp_path, '<service type="python:den.py:Watcher"/>')
    before = source.read_bytes()
    result = run(loops_cfg, end=5.0, extra=["--services", str(services), "--messages", str(source)], timeout=120)
    assert_bad_input(result, "--messages", str(source), "python:den.py:Watcher")
    assert source.read_bytes() == before
