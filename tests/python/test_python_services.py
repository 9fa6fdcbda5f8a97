"""Services written in Python (`<service type="python:FILE.py:Class"/>`, storyboard.services): they run on the
same middleware, radio and facilities as C++ services, so a Python beacon's trace is the C++ Beacon's byte for
byte, a Python and a C++ service logging the same calls log the same sequence, commands compose with stories,
statistics agree with the trace, and an exception is exit 2 naming the Python file and line."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pandas as pd
import pytest
from sbsim.messages import read_message_lines
from sbsim.runner import RunResult, run
from sbsim_helpers import assert_bad_input, assert_no_crash, services_file, write_file, write_story

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


def run_ok(cfg: Path, *extra: str, story: Path | None = None, end: float = 40.0) -> RunResult:
    result = run(cfg, story=story, end=end, seed=7, extra=list(extra), timeout=300)
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return result


@pytest.mark.parametrize("radio", ["disc", "channel"])
def test_python_beacon_trace_is_the_cpp_beacons_byte_for_byte(loops_cfg: Path, tmp_path: Path, radio: str) -> None:
    write_file(tmp_path, "beacon.py", BEACON)
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
    write_file(tmp_path, "calls.py", CALL_LOG)
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


MISTAKES = """
from storyboard.services import Service


class Boom(Service):
    def initialize(self) -> None:
        self.triggers = 0

    def trigger(self) -> None:
        self.triggers += 1
        if self.time > 5 and self.station_id == "veh03":
            self.record_scalar("before", self.triggers)
            print("printed before the error", flush=True)
            1 / 0  # the user's bug


class NotAService:
    pass


class WrongSignature(Service):
    def indicate(self) -> None:
        pass


class Declared(Service):
    attributes = {"limit": float}
"""


def test_an_exception_is_exit_2_naming_service_station_time_file_and_line(loops_cfg: Path, tmp_path: Path) -> None:
    source = write_file(tmp_path, "mistakes.py", MISTAKES)
    services = services_file(tmp_path, '<service type="CaService"/>', '<service type="python:mistakes.py:Boom"/>')
    trace = tmp_path / "trace.jsonl"
    result = run(loops_cfg, end=40.0, seed=7, extra=["--services", str(services), "--messages", str(trace)])
    assert_no_crash(result)
    assert result.returncode == 2, result.stderr
    last = result.stderr.splitlines()[-1]
    line = next(n for n, text in enumerate(source.read_text().splitlines(), 1) if "the user's bug" in text)
    for needle in ("python:mistakes.py:Boom", "vehicle veh03", "at t=5.", f"{source}:{line}", "ZeroDivisionError"):
        assert needle in last, (needle, last)
    assert "Traceback" in result.stderr
    # Nothing written is lost: what the service printed, and the trace so far (left .incomplete).
    assert "printed before the error" in result.stdout
    assert not trace.exists()
    assert Path(str(trace) + ".incomplete").stat().st_size > 0


@pytest.mark.parametrize(
    ("entry", "needle"),
    [
        ('type="python:missing.py:Boom"', "no such file"),
        ('type="python:mistakes.py:Nope"', "defines no class 'Nope'"),
        ('type="python:mistakes.py:NotAService"', "not a class derived from storyboard.services.Service"),
        ('type="python:mistakes.py:WrongSignature"', "WrongSignature.indicate must take"),
        ('type="python:mistakes.py:Declared" speed="3"', "unknown attribute 'speed'"),
        ('type="python:mistakes.py:Declared" limit="fast"', "attribute 'limit' must be a number"),
        ('type="python:no_such_package.apps:Boom"', "cannot import module 'no_such_package.apps'"),
    ],
)
@pytest.mark.parametrize("command", ["run", "check"])
def test_mistakes_are_refused_before_the_run(
    loops_cfg: Path, tmp_path: Path, entry: str, needle: str, command: str
) -> None:
    write_file(tmp_path, "mistakes.py", MISTAKES)
    services = services_file(tmp_path, f"<service {entry}/>")
    extra = ["check"] if command == "check" else []
    result = run(loops_cfg, end=10.0, extra=[*extra, "--services", str(services)], timeout=120)
    assert_bad_input(result, f"{services}:2:", needle)


#: A package on the story's path: the class lives in mypkg/apps.py, and the package's __init__ names it too.
PACKAGE_APPS = """
from storyboard.services import Service


class Quiet(Service):
    def trigger(self) -> None:
        pass
"""


@pytest.mark.parametrize("module", ["mypkg.apps", "mypkg"])
def test_a_module_named_services_files_are_inputs_no_output_may_overwrite(
    loops_cfg: Path, tmp_path: Path, module: str
) -> None:
    package = tmp_path / "mypkg"
    package.mkdir()
    apps = write_file(package, "apps.py", PACKAGE_APPS)
    init = write_file(package, "__init__.py", "from mypkg.apps import Quiet\n")
    services = services_file(tmp_path, f'<service type="python:{module}:Quiet"/>')
    # The class's module and, named through the package, the package's __init__ too: known only once imported.
    for target in [apps, init] if module == "mypkg" else [apps]:
        before = target.read_bytes()
        result = run(loops_cfg, end=5.0, extra=["--services", str(services), "--events", str(target)], timeout=120)
        assert_bad_input(result, "--events", str(target), f"python:{module}:Quiet")
        assert target.read_bytes() == before
    # Another output is fine.
    run_ok(loops_cfg, "--services", str(services), "--events", str(tmp_path / "events.jsonl"), end=5.0)


COMMANDS = """
from storyboard.services import Service


class Slow(Service):
    \"\"\"Caps veh01 at 3 m/s from 20 s to 40 s and paints it, through the effect stack.\"\"\"

    def trigger(self) -> None:
        if self.station_id != "veh01":
            return
        if 20 <= self.time < 40:
            self.set_max_speed(3.0)
            self.set_color(255, 0, 0)
        elif self.time >= 40:
            self.end_max_speed()
            self.end_color()
        self.emit("speed", self.speed or 0.0)
"""

#: A story capping veh01 at 6 m/s from 10 s to 30 s: the latest cap rules, the service's until 40 s.
CAP_STORY = """
from storyboard import AndCondition, CarSetCondition, SpeedEffect, Story, TimeCondition

def createStories(board):
    board.registerStory(Story(AndCondition(TimeCondition(10, 30), CarSetCondition(["veh01"])), [SpeedEffect(6.0)]))
"""


def test_commands_compose_with_stories_and_are_restored(loops_cfg: Path, tmp_path: Path) -> None:
    write_file(tmp_path, "commands.py", COMMANDS)
    story = write_story(tmp_path, CAP_STORY)
    services = services_file(tmp_path, '<service type="python:commands.py:Slow"/>')
    stats = tmp_path / "stats.parquet"
    run_ok(loops_cfg, "--services", str(services), "--statistics", str(stats), story=story, end=70.0)
    speed = pd.read_parquet(stats).query("name == 'speed'").set_index("time")["value"]

    def top(begin: float, end: float) -> float:
        return float(speed[(speed.index > begin) & (speed.index <= end)].max())

    assert top(2, 10) > 7.0  # free
    assert top(13, 20) <= 6.0 + 1e-6  # the story's cap
    assert top(23, 40) <= 3.0 + 1e-6  # the service's, the latest, outlives the story's end
    assert top(48, 70) > 7.0  # both ended: the vehicle's own max speed is back


def test_threads_do_not_change_the_trace_or_the_statistics(loops_cfg: Path, tmp_path: Path) -> None:
    write_file(tmp_path, "beacon.py", BEACON)
    write_file(tmp_path, "calls.py", CALL_LOG)
    services = services_file(
        tmp_path,
        '<service type="CaService"/>',
        '<service type="python:beacon.py:PyBeacon" interval="0.3"/>',
        '<service type="python:calls.py:BatchLog"/>',
    )
    outputs = {}
    for threads in ("1", "2"):
        trace, stats = tmp_path / f"t{threads}.jsonl", tmp_path / f"t{threads}.parquet"
        run_ok(
            loops_cfg,
            "--services",
            str(services),
            "--messages",
            str(trace),
            "--statistics",
            str(stats),
            "--threads",
            threads,
        )
        outputs[threads] = (trace.read_bytes(), pd.read_parquet(stats))
    assert outputs["1"][0] == outputs["2"][0]
    assert outputs["1"][1].equals(outputs["2"][1])


ROADSIDE = """
from storyboard.services import Service


class Announcer(Service):
    \"\"\"On a roadside unit: sends a hazard with a payload every second; it has no vehicle to command.\"\"\"

    def initialize(self):
        assert self.is_roadside_unit and self.speed is None
        self.sent = 0
        self.schedule_after(1.0, self.announce)

    def announce(self):
        x, y = self.position
        self.send("Hazard", 64, {"at": [x, y], "n": self.sent, "by": self.station_id})
        self.sent += 1
        self.schedule_after(1.0, self.announce)

    def finish(self):
        self.record_scalar("sent", self.sent)
        try:
            self.set_max_speed(3.0)
        except RuntimeError as e:
            self.record_scalar("refused" if "roadside unit" in str(e) else "other", 1)


class Listener(Service):
    def initialize(self):
        self.heard = 0

    def indicate(self, message):
        if message.type != "Hazard":
            return
        payload = message.payload
        assert payload["by"] == message.sender == "rsu0" and payload["at"] == (300.0, 300.0)
        assert isinstance(payload["n"], int)
        self.heard += 1

    def finish(self):
        self.record_scalar("hazards", self.heard)
"""


def test_a_roadside_units_python_service_sends_payloads_vehicles_read(loops_cfg: Path, tmp_path: Path) -> None:
    write_file(tmp_path, "roadside.py", ROADSIDE)
    services = services_file(
        tmp_path,
        '<service type="python:roadside.py:Listener"/>',
        '<rsu id="rsu0" x="300" y="300"><service type="python:roadside.py:Announcer"/></rsu>',
    )
    trace, stats = tmp_path / "trace.jsonl", tmp_path / "stats.parquet"
    run_ok(loops_cfg, "--services", str(services), "--messages", str(trace), "--statistics", str(stats))
    table = pd.read_parquet(stats)
    scalars = table.groupby("name")["value"].sum()
    lines = read_message_lines(trace)
    assert scalars["sent"] == sum(1 for line in lines if line["event"] == "tx" and line["type"] == "Hazard") > 30
    assert scalars["refused"] == 1 and "other" not in scalars
    # What the listeners heard is what the trace says they received.
    assert scalars["hazards"] == sum(1 for line in lines if line["event"] == "rx" and line["type"] == "Hazard") > 0


def test_the_python_warning_story_warns_more_vehicles_and_further_as_more_are_equipped(tmp_path: Path) -> None:
    folder = Path(__file__).resolve().parents[2] / "stories" / "python-warning"
    warned, furthest = {}, {}
    for penetration in ("0.25", "1"):
        stats = tmp_path / f"{penetration}.parquet"
        result = run(
            folder / "warning.sumocfg",
            story=folder / "story.py",
            extra=[
                "--services",
                str(folder / "services.xml"),
                "--penetration",
                penetration,
                "--statistics",
                str(stats),
            ],
            timeout=300,
        )
        assert_no_crash(result)
        assert result.returncode == 0, result.stderr
        table = pd.read_parquet(stats)
        distances = table[table["name"] == "warning_distance"]
        hops = table[table["name"] == "warning_hops"]
        assert distances["equipped"].all() and set(hops["value"]) <= {1, 2, 3}
        # Ahead of the hazard (x = 1,490 m, the crash car's stop), never before the road's start.
        assert ((distances["value"] > 0) & (distances["value"] < 1490)).all()
        warned[penetration] = distances["vehicle"].nunique()
        furthest[penetration] = distances["value"].max()
    assert 0 < warned["0.25"] < warned["1"]
    # The unit alone (500 m around x = 1,190 m) reaches 800 m before the hazard; relays carry it further.
    assert furthest["1"] > 800
