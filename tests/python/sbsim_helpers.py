"""Helpers shared by sbsim's Python tests: running stories, reading event logs and SUMO's FCD output."""

from __future__ import annotations

import os
import re
import subprocess
import textwrap
import time
from collections import defaultdict
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest
from sbsim.fcd import read_timesteps
from sbsim.runner import RunResult, cmake_prefix, executable, read_events, run

#: The repository's root and its ready scenarios.
REPO = Path(__file__).resolve().parents[2]
STORIES = REPO / "stories"
#: Test-local service modules (SpeedStatisticsService, ThrowingService), built by conftest.services_module.
SERVICES_SOURCE = REPO / "tests" / "python" / "plugins" / "services"

#: convBoundary written into the offset scenario's net (conftest.offset_cfg): xmin, ymin, xmax, ymax.
OFFSET_BOUNDARY = (-100.0, -50.0, 700.0, 650.0)

#: Summary lines that differ from run to run even with the same seed.
TIMING_KEYS = ("wall time:", "real-time factor:", "time in sumo:", "time reading vehicles:", "time in storyboard:")

#: What a C++ crash looks like on stderr.
CRASH_MARKERS = (
    "terminate called",
    "Aborted",
    "core dumped",
    "Segmentation fault",
    "what():",
    # Sanitizer reports (./run-tests --sanitize).
    "AddressSanitizer",
    "LeakSanitizer",
    "runtime error:",
)


def stable_stdout(stdout: str) -> str:
    """stdout without the timing lines (wall time, time in SUMO and so on, real-time factor)."""
    return "\n".join(line for line in stdout.splitlines() if not line.startswith(TIMING_KEYS))


def assert_no_crash(result: RunResult) -> None:
    for marker in CRASH_MARKERS:
        assert marker not in result.stderr, f"sbsim crashed ({marker!r}):\n{result.stderr}"
    assert result.returncode >= 0, f"sbsim was killed by signal {-result.returncode}:\n{result.stderr}"


def wait_until(
    ready: Callable[[], bool], what: str, proc: subprocess.Popen[Any] | None = None, timeout: float = 60.0
) -> None:
    """Returns once ``ready()`` holds (a marker the program or its story writes once it got somewhere,
    processes gone), polling: a test never waits a fixed time for a process to get somewhere, which
    depends on the machine's speed. Fails if ``proc`` ended first (it is then not going to get there) or
    ``timeout`` passed (``proc`` is then killed)."""
    deadline = time.monotonic() + timeout
    while not ready():
        if proc is not None and proc.poll() is not None:
            pytest.fail(f"the process ended (exit {proc.returncode}) before {what}")
        if time.monotonic() > deadline:
            if proc is not None:
                proc.kill()
                proc.wait()
            pytest.fail(f"not {what} within {timeout:.0f} s")
        time.sleep(0.01)


def wait_for_file(proc: subprocess.Popen[Any], marker: Path, timeout: float = 60.0) -> None:
    """Returns once ``marker`` exists (a story touches it once the run is where a test wants it)."""
    wait_until(marker.exists, f"it created {marker.name}", proc, timeout)


def write_story(directory: Path, source: str, name: str = "story.py") -> Path:
    path = Path(directory) / name
    path.write_text(textwrap.dedent(source), encoding="utf-8")
    return path


def write_file(directory: Path, name: str, text: str) -> Path:
    """`text`, dedented and without its leading blank lines, as `directory/name`."""
    path = Path(directory) / name
    path.write_text(textwrap.dedent(text).lstrip(), encoding="utf-8")
    return path


def services_file(directory: Path, *entries: str, name: str = "services.xml") -> Path:
    """A services file holding `entries` (XML elements) in a <services> element."""
    return write_file(directory, name, "<services>\n" + "\n".join(f"  {e}" for e in entries) + "\n</services>\n")


@dataclass
class FcdTrace:
    """Per-vehicle states from SUMO's ``--fcd-output``, keyed by sbsim time.

    SUMO labels a state with the time at the *start* of the step that produced it, while sbsim (and its
    event log) uses the time *after* the step; so FCD time ``T`` is sbsim time ``T + step``.
    """

    times: list[float] = field(default_factory=list)
    running: dict[float, set[str]] = field(default_factory=dict)
    speed: dict[str, dict[float, float]] = field(default_factory=lambda: defaultdict(dict))
    pos: dict[str, dict[float, tuple[float, float]]] = field(default_factory=lambda: defaultdict(dict))
    #: SUMO lane id (``<edge>_<index>``) per vehicle and sbsim time.
    lane: dict[str, dict[float, str]] = field(default_factory=lambda: defaultdict(dict))
    #: SUMO vehicle type id per vehicle and sbsim time.
    type: dict[str, dict[float, str]] = field(default_factory=lambda: defaultdict(dict))

    def speeds(self, vehicle: str, t0: float = float("-inf"), t1: float = float("inf")) -> dict[float, float]:
        """Speeds of ``vehicle`` at sbsim times in [t0, t1] (only where it was running)."""
        return {t: v for t, v in self.speed.get(vehicle, {}).items() if t0 <= t <= t1}


def read_fcd(path: Path, step: float = 1.0) -> FcdTrace:
    """The FCD (:func:`sbsim.fcd.read_timesteps`) indexed the way the tests ask it."""
    trace = FcdTrace()
    for timestep in read_timesteps(path, step=step):
        t = timestep.t
        trace.times.append(t)
        trace.running[t] = set()
        for v in timestep.vehicles:
            trace.running[t].add(v.vehicle)
            trace.speed[v.vehicle][t] = v.speed
            trace.pos[v.vehicle][t] = (v.x, v.y)
            if v.lane is not None:
                trace.lane[v.vehicle][t] = v.lane
            if v.type is not None:
                trace.type[v.vehicle][t] = v.type
    return trace


@dataclass
class StoryRun:
    result: RunResult
    events: list[dict[str, Any]]
    fcd: FcdTrace | None
    story: Path

    @property
    def returncode(self) -> int:
        return self.result.returncode

    def of(self, **match: Any) -> list[dict[str, Any]]:
        """Events whose fields equal all of ``match``."""
        return [e for e in self.events if all(e.get(k) == v for k, v in match.items())]

    def activated(self, story: str) -> list[str]:
        return [e["vehicle"] for e in self.of(type="activate", story=story)]


def run_story(
    sumocfg: Path,
    source: str,
    directory: Path,
    *,
    end: float | None = None,
    seed: int | None = None,
    fcd: bool = False,
    sumo_options: tuple[str, ...] = (),
    extra: tuple[str, ...] = (),
    name: str = "story.py",
    check: bool = True,
) -> StoryRun:
    """Writes ``source`` as a story into ``directory`` and runs it with ``--events`` (and FCD output if asked)."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    story = write_story(directory, source, name)
    events_path = directory / (Path(name).stem + ".events.jsonl")
    options = list(sumo_options)
    fcd_path = directory / (Path(name).stem + ".fcd.xml")
    if fcd:
        options += [f"--fcd-output {fcd_path}", "--precision 6"]
    result = run(
        sumocfg, story=story, events=events_path, end=end, seed=seed, sumo_options=options, extra=extra, timeout=120
    )
    assert_no_crash(result)
    if check:
        assert result.returncode == 0, f"sbsim failed ({result.returncode}):\n{result.stderr}"
    events = read_events(events_path) if events_path.exists() else []
    trace = read_fcd(fcd_path) if fcd and result.returncode == 0 else None
    return StoryRun(result, events, trace, story)


def byte_key(vehicle_id: str) -> bytes:
    return vehicle_id.encode("utf-8")


def env_without(*names: str) -> dict[str, str]:
    return {k: v for k, v in os.environ.items() if k not in names}


def active_timeline(events: list[dict[str, Any]], story: str, times: list[float]) -> dict[float, frozenset[str]]:
    """The vehicles for which ``story`` is active after the evaluation at each of ``times``, from the event log."""
    by_time: dict[float, list[dict[str, Any]]] = defaultdict(list)
    for e in events:
        if e["story"] == story:
            by_time[float(e["t"])].append(e)
    active: set[str] = set()
    out: dict[float, frozenset[str]] = {}
    for t in sorted(set(times) | set(by_time)):
        for e in by_time.get(t, []):
            if e["type"] == "activate":
                assert e["vehicle"] not in active, f"{story}: {e['vehicle']} activated twice at {t}"
                active.add(e["vehicle"])
            elif e["type"] == "deactivate":
                assert e["vehicle"] in active, f"{story}: {e['vehicle']} deactivated while inactive at {t}"
                active.remove(e["vehicle"])
        out[t] = frozenset(active)
    return {t: out[t] for t in times}


def assert_active_as_predicted(
    run: StoryRun,
    story: str,
    predicate: Any,
    *,
    ambiguous: Any = None,
) -> int:
    """At every step, ``story`` is active for exactly the running vehicles (per FCD) where
    ``predicate(vehicle, t)`` holds; vehicles where ``ambiguous(vehicle, t)`` are not checked.
    Returns how many (vehicle, step) pairs were predicted active (so tests can require some)."""
    assert run.fcd is not None
    timeline = active_timeline(run.events, story, run.fcd.times)
    positives = 0
    for t in run.fcd.times:
        running = run.fcd.running[t]
        considered = {v for v in running if not (ambiguous and ambiguous(v, t))}
        predicted = {v for v in considered if predicate(v, t)}
        actual = timeline[t] & considered
        positives += len(predicted)
        assert actual == predicted, (
            f"{story} at t={t}: active but not predicted {sorted(actual - predicted)}, "
            f"predicted but not active {sorted(predicted - actual)}"
        )
        assert timeline[t] <= running, f"{story} at t={t}: active for vehicles not running {timeline[t] - running}"
    return positives


def message_counts(stdout: str) -> dict[str, tuple[int, int]]:
    """The summary's ``messages <Type>: sent N[, forwarded F], delivered M`` lines, as {type: (sent, delivered)}."""
    out: dict[str, tuple[int, int]] = {}
    for line in stdout.splitlines():
        m = re.fullmatch(r"messages (\S+): sent (\d+)(?:, forwarded \d+)?, delivered (\d+)", line.strip())
        if m:
            out[m.group(1)] = (int(m.group(2)), int(m.group(3)))
    return out


def assert_bad_input(result: RunResult, *needles: str) -> str:
    """Exit 2, nothing on stdout, exactly one stderr line (starting with "sbsim") that contains every
    needle; returns the line."""
    assert_no_crash(result)
    assert result.returncode == 2, f"exit {result.returncode}, stderr:\n{result.stderr}"
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, f"expected one line on stderr, got {len(lines)}:\n{result.stderr}"
    line = lines[0]
    assert line.startswith("sbsim"), line
    for needle in needles:
        assert needle in line, f"{needle!r} not in {line!r}"
    assert result.stdout == "", f"unexpected stdout:\n{result.stdout}"
    return line


def sdk_prefix(directory: Path) -> Path:
    """The C++ SDK of the sbsim under test: installed from its build folder when it is one (so a
    plugin sees this build's headers), else the one pip installed."""
    build = executable().parent
    if not (build / "CMakeCache.txt").is_file():
        return cmake_prefix()
    prefix = directory / "sdk"
    done = subprocess.run(
        ["cmake", "--install", str(build), "--prefix", str(prefix)], capture_output=True, text=True, check=False
    )
    if done.returncode != 0:
        pytest.fail(f"installing the SDK failed:\n{done.stdout}\n{done.stderr}")
    return prefix


def netgenerate_grid(out: Path, name: str, *options: str, end: float = 60) -> Path:
    """A grid network netgenerate makes in `out` (`--grid` with `options`, no U-turns, seed 1) and a
    sumocfg of it (0.1 s steps from 0 to `end`); returns the sumocfg."""
    import sumo

    net = out / f"{name}.net.xml"
    command = [str(Path(sumo.SUMO_HOME) / "bin" / "netgenerate"), "--grid", *options]
    subprocess.run([*command, "--no-turnarounds=true", "--seed=1", "-o", str(net)], check=True, capture_output=True)
    cfg = out / f"{name}.sumocfg"
    cfg.write_text(
        f'<configuration><input><net-file value="{net.name}"/></input>'
        f'<time><begin value="0"/><end value="{end:g}"/><step-length value="0.1"/></time></configuration>\n'
    )
    return cfg
