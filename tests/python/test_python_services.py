"""Services written in Python (`<service type="python:FILE.py:Class"/>`, storyboard.services): they run on the
same middleware, radio and facilities as C++ services, so a Python beacon's trace is the C++ Beacon's byte for
byte, a Python and a C++ service logging the same calls log the same sequence, commands compose with stories,
statistics agree with the trace, and an exception is exit 2 naming the Python file and line."""

from __future__ import annotations

import textwrap
from collections import Counter
from pathlib import Path

import pandas as pd
import pytest
from sbsim.messages import read_message_lines
from sbsim.runner import RunResult, run
from sbsim_helpers import SERVICES_SOURCE, assert_bad_input, assert_no_crash, write_story

BEACON = """
from storyboard.services import Service


class PyBeacon(Service):
    \"\"\"sbsim's Beacon in Python, counting what it hears.\"\"\"

    attributes = {"interval": float, "bytes": int}

    def initialize(self) -> None:
        self.interval = self.attribute("interval", 0.1)
        self.bytes = self.attribute("bytes", 190)
        self.heard = 0
        self.schedule_after(self.start_phase(self.interval), self.beacon)

    def beacon(self) -> None:
        self.send("Beacon", self.bytes, security="cam")
        self.schedule_after(self.interval, self.beacon)

    def indicate(self, message) -> None:
        self.heard += 1

    def finish(self) -> None:
        self.record_scalar("heard", self.heard)
"""

#: Logs each call as the C++ CallLogService (tests/python/plugins/services) does.
CALL_LOG = """
from storyboard.services import Service


class CallLog(Service):
    def initialize(self): self.emit("call", 1)
    def trigger(self): self.emit("call", 2)
    def receive_signal(self, signal): self.emit("call", 3)
    def indicate(self, message):
        self.emit("call", 4)
        self.emit("indicate", message.sequence)
    def on_cam(self, cam): self.emit("call", 5)
    def on_denm(self, denm): self.emit("call", 6)
    def finish(self): self.emit("call", 7)


class BatchLog(Service):
    \"\"\"The receptions through indicate_batch: the same messages in the same order, delivered before trigger().\"\"\"

    def indicate_batch(self, messages):
        assert len(messages.received_at) == len(messages) == len(messages.senders)
        for message in messages:
            self.emit("indicate", message.sequence)
"""

SIGNAL_STORY = """
from storyboard import CarSetCondition, SignalEffect, Story, TimeCondition, AndCondition

def createStories(board):
    when = AndCondition(TimeCondition(10, 20), CarSetCondition(["veh01", "veh02"]))
    board.registerStory(Story(when, [SignalEffect("hello", "bye")], name="greet"))
"""


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.write_text(textwrap.dedent(text).lstrip(), encoding="utf-8")
    return path


def services_file(directory: Path, *entries: str, name: str = "services.xml") -> Path:
    return write(directory, name, "<services>\n" + "\n".join(f"  {e}" for e in entries) + "\n</services>\n")


def run_ok(cfg: Path, *extra: str, story: Path | None = None, end: float = 40.0) -> RunResult:
    result = run(cfg, story=story, end=end, seed=7, extra=list(extra), timeout=300)
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return result


@pytest.mark.parametrize("radio", ["disc", "channel"])
def test_python_beacon_trace_is_the_cpp_beacons_byte_for_byte(loops_cfg: Path, tmp_path: Path, radio: str) -> None:
    write(tmp_path, "beacon.py", BEACON)
    cpp = services_file(tmp_path, '<service type="Beacon" interval="0.2" bytes="300"/>', name="cpp.xml")
    py = services_file(tmp_path, '<service type="python:beacon.py:PyBeacon" interval="0.2" bytes="300"/>')
    extra = ["--radio", str(Path(__file__).resolve().parents[2] / "bench" / "radio.toml")] if radio == "channel" else []
    traces = {}
    for name, services in (("cpp", cpp), ("py", py)):
        trace = tmp_path / f"{name}.jsonl"
        stats = tmp_path / f"{name}.parquet"
        run_ok(loops_cfg, "--services", str(services), "--messages", str(trace), "--statistics", str(stats), *extra)
        traces[name] = trace.read_bytes()
    assert traces["cpp"] == traces["py"]
    lines = read_message_lines(tmp_path / "py.jsonl")
    assert Counter(line["event"] for line in lines)["tx"] > 1000
    # What each Python beacon counted is its receptions in the trace.
    table = pd.read_parquet(tmp_path / "py.parquet")
    heard = table[table["name"] == "heard"].set_index("vehicle")["value"].astype(int)
    rx = Counter(line["station"] for line in lines if line["event"] == "rx")
    assert heard.sum() > 0
    assert {v: n for v, n in heard.items() if n} == dict(rx)


def test_python_and_cpp_services_see_the_same_calls(loops_cfg: Path, services_module: Path, tmp_path: Path) -> None:
    write(tmp_path, "calls.py", CALL_LOG)
    story = write_story(tmp_path, SIGNAL_STORY)
    services = services_file(
        tmp_path,
        '<service type="CaService"/>',
        '<service type="CallLogService"/>',
        '<service type="python:calls.py:CallLog"/>',
        '<service type="python:calls.py:BatchLog"/>',
    )
    stats = tmp_path / "stats.parquet"
    run_ok(
        loops_cfg,
        "--plugin",
        str(services_module),
        "--services",
        str(services),
        "--statistics",
        str(stats),
        story=story,
    )
    table = pd.read_parquet(stats)
    cpp = table[table["source"] == "CallLogService"]
    py = table[table["source"] == "python:calls.py:CallLog"]
    batch = table[table["source"] == "python:calls.py:BatchLog"]
    columns = ["vehicle", "name", "time", "value"]
    assert len(cpp) > 1000
    assert set(cpp["value"][cpp["name"] == "call"]) == {1, 2, 3, 4, 5, 7}  # no DENMs here
    # Row for row: the same calls, at the same times, in the same order.
    assert cpp[columns].reset_index(drop=True).equals(py[columns].reset_index(drop=True))
    # The batch has the same receptions in the same order per vehicle (delivered later, at triggers).
    for vehicle, rows in cpp[cpp["name"] == "indicate"].groupby("vehicle"):
        got = batch[(batch["vehicle"] == vehicle) & (batch["name"] == "indicate")]
        assert list(got["value"]) == list(rows["value"])  # finish() hands over the last batch
