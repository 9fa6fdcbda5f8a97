"""Scenario criteria: each built-in passes on one generated run and fails on another; the verdicts
in the summary (text and JSON), --junit (read with an XML parser), exit code 3, sbsim check."""

from __future__ import annotations

import json
import re
import textwrap
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from pathlib import Path

import pytest
from sbsim.runner import RunResult, read_events, run
from sbsim.scenarios.grid import make_grid
from sbsim_helpers import STORIES, assert_bad_input, assert_no_crash, write_story

# The loops scenario (conftest.loops_cfg): a 3 x 3 grid, 200 m blocks, one lane, 30 vehicles veh00..veh29.
INSIDE = [(-50.0, -50.0), (1000.0, -50.0), (1000.0, 1000.0), (-50.0, 1000.0)]  # the whole net
OUTSIDE = [(5000.0, 5000.0), (5100.0, 5000.0), (5100.0, 5100.0)]

HEADER = """
from storyboard import *

class Ram(Effect):
    # Speed checks off and full throttle: the vehicle drives into whoever is ahead.
    def apply(self, vehicle):
        vehicle.set_speed_mode(0)
        vehicle.set_speed(40.0)

    def remove(self, vehicle):
        pass

"""


def run_criteria(
    cfg: Path, directory: Path, body: str, end: float | None = 120.0, extra: Sequence[str] = ()
) -> tuple[RunResult, dict, ET.Element]:
    directory.mkdir(parents=True, exist_ok=True)
    story = write_story(directory, HEADER + "def createStories(board):\n" + body)
    summary, junit = directory / "summary.json", directory / "junit.xml"
    result = run(
        cfg,
        story=story,
        end=end,
        seed=2,
        extra=["--summary", str(summary), "--junit", str(junit), *extra],
        timeout=180,
    )
    assert_no_crash(result)
    assert result.returncode in (0, 3), result.stderr
    return result, json.loads(summary.read_text(encoding="utf-8")), ET.parse(junit).getroot()


def verdict_of(
    cfg: Path, directory: Path, criterion: str, stories: str = "", end: float | None = 120.0, extra: Sequence[str] = ()
) -> dict:
    """Runs one criterion (after `stories`, lines of createStories) and returns its JSON entry,
    checking that exit code, text summary and JUnit say the same."""
    body = "".join(f"    {line}\n" for line in [*stories.splitlines(), f"board.registerCriterion({criterion})"] if line)
    result, summary, junit = run_criteria(cfg, directory, body, end, extra)
    [entry] = summary["criteria"]
    assert summary["verdict"] == ("passed" if entry["passed"] else "failed")
    assert result.returncode == (0 if entry["passed"] else 3), result.stderr
    status = "passed" if entry["passed"] else "FAILED"
    line = f"criterion {entry['name']}: {status} (actual: {entry['actual']}; expected: {entry['expected']})"
    assert line in result.stdout.splitlines(), result.stdout
    [suite] = junit.findall("testsuite")
    [case] = suite.findall("testcase")
    assert case.get("name") == entry["name"]
    assert suite.get("tests") == "1" and suite.get("failures") == ("0" if entry["passed"] else "1")
    failure = case.find("failure")
    if entry["passed"]:
        assert failure is None
    else:
        assert failure is not None
        assert entry["actual"] in failure.get("message", "") and entry["expected"] in failure.get("message", "")
    return entry


@pytest.fixture(scope="module")
def two_lanes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The loops scenario with two lanes per direction: SUMO's drivers change lanes."""
    return make_grid(
        tmp_path_factory.mktemp("two-lanes"),
        grid=3,
        lanes=2,
        end=300.0,
        seed=3,
        traffic="loops",
        vehicles=30,
        ramp=30.0,
    )


def test_no_collision(loops_cfg: Path, tmp_path: Path) -> None:
    ok = verdict_of(loops_cfg, tmp_path / "ok", "NoCollision()")
    assert ok["passed"] and ok["actual"] == "0 collisions", ok
    rams = "board.registerStory(Story(AndCondition(TimeCondition(40), CarSetCondition(['veh03'])), [Ram()]))"
    crash = verdict_of(loops_cfg, tmp_path / "crash", "NoCollision()", rams)
    assert not crash["passed"] and "veh03" in crash["actual"], crash


def test_max_speed(loops_cfg: Path, tmp_path: Path) -> None:
    # The net's limit is 13.89 m/s; SUMO's drivers exceed it by their speed factor, not by twice.
    ok = verdict_of(loops_cfg, tmp_path / "ok", "MaxSpeed(28.0)")
    assert ok["passed"], ok
    fast = verdict_of(loops_cfg, tmp_path / "fast", "MaxSpeed(5.0, vehicles=['veh01', 'veh02'])")
    assert not fast["passed"] and fast["expected"] == "<= 5 m/s", fast
    assert float(fast["actual"].split()[0]) > 5.0 and fast["actual"].split()[2] in ("(veh01", "(veh02"), fast


def test_reached_region(loops_cfg: Path, tmp_path: Path) -> None:
    ok = verdict_of(loops_cfg, tmp_path / "ok", f"ReachedRegion('veh00', {INSIDE}, by=60)")
    assert ok["passed"] and ok["actual"].startswith("reached at t="), ok
    never = verdict_of(loops_cfg, tmp_path / "never", f"ReachedRegion('veh00', {OUTSIDE}, by=60)")
    assert not never["passed"] and never["actual"] == "never reached", never


def test_keeps_lane(loops_cfg: Path, two_lanes: Path, tmp_path: Path) -> None:
    ok = verdict_of(loops_cfg, tmp_path / "ok", "KeepsLane()")  # one lane: nowhere to change to
    assert ok["passed"] and ok["actual"] == "0 lane changes", ok
    # On two lanes, veh01 is sent to the left lane at 40 s and back at 80 s.
    moves = (
        "board.registerStory(Story(AndCondition(TimeCondition(40, 80), CarSetCondition(['veh01'])), [LaneEffect(1)]))\n"
        "board.registerStory(Story(AndCondition(TimeCondition(80), CarSetCondition(['veh01'])), [LaneEffect(0)]))"
    )
    changes = verdict_of(two_lanes, tmp_path / "changes", "KeepsLane(vehicles=['veh01'])", moves)
    assert not changes["passed"] and "veh01" in changes["actual"], changes


def test_no_red_light_running(loops_cfg: Path, tmp_path: Path) -> None:
    # The loops grid has traffic lights at its inner junctions; SUMO's drivers stop for red.
    ok = verdict_of(loops_cfg, tmp_path / "ok", "NoRedLightRunning()")
    assert ok["passed"] and ok["actual"] == "0 red-light passages", ok
    # From 10 s, five drivers ignore red lights: speed mode 15 lacks bit 4 ("brake hard for red").
    reckless = (
        "class IgnoreRed(Effect):\n"
        "    def apply(self, vehicle):\n"
        "        vehicle.set_speed_mode(15)\n"
        "    def remove(self, vehicle):\n"
        "        pass\n"
        "ids = ['veh01', 'veh02', 'veh03', 'veh04', 'veh05']\n"
        "board.registerStory(Story(AndCondition(TimeCondition(10), CarSetCondition(ids)), [IgnoreRed()]))"
    )
    red = verdict_of(loops_cfg, tmp_path / "red", "NoRedLightRunning()", reckless)
    assert not red["passed"] and red["expected"] == "0 red-light passages", red
    runners = red["actual"].split("(")[1].split(")")[0].split(", ")
    assert runners and set(runners) <= {"veh01", "veh02", "veh03", "veh04", "veh05"}, red
    # Only the reckless five: the others, watched alone, still pass.
    others = ", ".join(repr(f"veh{k:02d}") for k in range(6, 30))
    rest = verdict_of(loops_cfg, tmp_path / "rest", f"NoRedLightRunning(vehicles=[{others}])", reckless)
    assert rest["passed"], rest


def test_no_red_light_running_ignores_teleports_and_a_story_switching_a_light(loops_cfg: Path, tmp_path: Path) -> None:
    # Every light of the loops grid held all red for 8 s every 20 s: the loops jam, SUMO teleports the
    # vehicles stuck for 120 s onto their next road (10 of them over a red light's line, counted as
    # red-light passages before teleports were told apart), and a hold that begins in a step when a
    # vehicle crossed on green made a criterion reading the light after the stories see red (1).
    lights = {"A1": 6, "B0": 6, "B1": 12, "B2": 6, "C1": 6}
    holds = "\n".join(
        f"board.registerStory(WorldStory(TimeCondition({20 * k}, {20 * k + 8}), "
        f"[TrafficLightEffect({tls!r}, {'r' * n!r})], name='red-{tls}-{k}'))"
        for k in range(1, 14)
        for tls, n in lights.items()
    )
    statistics = tmp_path / "sumo-statistics.xml"
    entry = verdict_of(
        loops_cfg,
        tmp_path / "holds",
        "NoRedLightRunning()",
        holds,
        end=300.0,
        extra=["--sumo-option", f"--statistic-output {statistics}"],
    )
    assert entry["passed"] and entry["actual"] == "0 red-light passages", entry
    teleports = ET.parse(statistics).getroot().find("teleports")
    assert teleports is not None and int(teleports.get("total", "0")) > 0  # the jam did happen


MOTORWAY = STORIES / "motorway-accident"
# The motorway-accident story as it is (the crash at x = 1,490 m from 40 s, its DENM, cause 2), and
# a 40 m stretch of all three lanes around the crash.
ACCIDENT_STORY = (
    f"import sys\nsys.path.insert(0, {str(MOTORWAY)!r})\nfrom story import createStories\ncreateStories(board)"
)
AT_THE_CRASH = [(1470.0, -20.0), (1510.0, -20.0), (1510.0, 20.0), (1470.0, 20.0)]


def test_warned_before(tmp_path: Path) -> None:
    services = ["--services", str(MOTORWAY / "services.xml")]

    def warned(directory: str, seconds: float) -> dict:
        # From the crash until it is cleared: before, there is nothing to warn of; after, nobody is told.
        criterion = f"WarnedBefore({AT_THE_CRASH}, cause=2, seconds={seconds}, since=40, until=160)"
        return verdict_of(
            MOTORWAY / "motorway.sumocfg", tmp_path / directory, criterion, ACCIDENT_STORY, None, services
        )

    ok = warned("ok", 0)
    assert ok["passed"] and ok["actual"].startswith("0 of "), ok
    judged = int(ok["actual"].split()[2])
    assert judged > 50, ok  # every vehicle passing the crash in those 120 s, warned before it got there
    # Those close behind the crash at 40 s were warned when the DENM went out, seconds before they
    # arrived, not half a minute.
    late = warned("late", 30)
    assert not late["passed"] and late["expected"] == "0 vehicles reached it unwarned (warned >= 30 s before)", late
    unwarned = int(late["actual"].split()[0])
    assert 0 < unwarned < judged and f"of {judged} vehicles" in late["actual"], late
    # Warned by the first DENM: sent at the crash car's first trigger after 40 s (its own clock).
    warned_at = re.search(r"warned at t=([0-9.]+) s", late["actual"])
    assert warned_at and 40 < float(warned_at.group(1)) <= 40.101, late


def test_warned_before_needs_a_den_service(tmp_path: Path) -> None:
    body = "".join(
        f"    {line}\n" for line in [*ACCIDENT_STORY.splitlines(), "board.registerCriterion(WarnedBefore('highway'))"]
    )
    story = write_story(tmp_path, HEADER + "def createStories(board):\n" + body)
    done = run(MOTORWAY / "motorway.sumocfg", story=story, end=5.0, timeout=120)
    assert_bad_input(done, "WarnedBefore(edge highway, seconds=0)", "no DEN service runs")
    with_ca_only = tmp_path / "services.xml"
    with_ca_only.write_text('<services><service type="artery.application.CaService"/></services>')
    done = run(MOTORWAY / "motorway.sumocfg", story=story, end=5.0, extra=["--services", str(with_ca_only)])
    assert_bad_input(done, "no DEN service runs")


def test_warned_before_counts_a_roadside_unit_as_the_den_service(tmp_path: Path) -> None:
    # The registry says which services send DENMs: a unit at the crash announcing it, with the
    # vehicles running only the CA service, fills their DENM memories, so the run is not refused.
    services = tmp_path / "services.xml"
    services.write_text(
        '<services><service type="artery.application.CaService"/><rsu id="rsu0" x="1490" y="0">'
        '<service type="RsuDenService" cause="2" from="40" until="160" area="2000"/></rsu></services>'
    )
    criterion = f"WarnedBefore({AT_THE_CRASH}, cause=2, seconds=0, since=40, until=160)"
    entry = verdict_of(
        MOTORWAY / "motorway.sumocfg", tmp_path / "rsu", criterion, ACCIDENT_STORY, None, ["--services", str(services)]
    )
    assert entry["passed"] and entry["actual"].startswith("0 of "), entry
    assert int(entry["actual"].split()[2]) > 50, entry


#: A roadside unit at the crash announcing it from Python (send_denm), or a Python service that sends no DENMs.
PYTHON_UNIT = """
from storyboard.services import Service


class Crash(Service):
    sends_denms = True

    def initialize(self):
        self.schedule_after(40.0, lambda: self.send_denm(cause=2, area=2000.0, validity=120.0))


class Quiet(Service):
    pass
"""


def test_warned_before_counts_a_python_service_that_sends_denms(tmp_path: Path) -> None:
    (tmp_path / "crash.py").write_text(PYTHON_UNIT)
    services = tmp_path / "services.xml"
    criterion = f"WarnedBefore({AT_THE_CRASH}, cause=2, seconds=0, since=40, until=160)"
    for unit, accepted in (("Crash", True), ("Quiet", False)):
        services.write_text(
            '<services><service type="artery.application.CaService"/><rsu id="rsu0" x="1490" y="0">'
            f'<service type="python:crash.py:{unit}"/></rsu></services>'
        )
        if not accepted:
            body = "".join(
                f"    {line}\n" for line in [*ACCIDENT_STORY.splitlines(), f"board.registerCriterion({criterion})"]
            )
            story = write_story(tmp_path, HEADER + "def createStories(board):\n" + body)
            done = run(MOTORWAY / "motorway.sumocfg", story=story, end=5.0, extra=["--services", str(services)])
            assert_bad_input(done, "no DEN service runs", "sends_denms = True")
            continue
        entry = verdict_of(
            MOTORWAY / "motorway.sumocfg",
            tmp_path / unit,
            criterion,
            ACCIDENT_STORY,
            None,
            ["--services", str(services)],
        )
        assert entry["passed"] and entry["actual"].startswith("0 of "), entry
        assert int(entry["actual"].split()[2]) > 50, entry


def test_story_activated(loops_cfg: Path, tmp_path: Path) -> None:
    when = "AndCondition(TimeCondition(10), CarSetCondition(['veh01', 'veh02']))"
    story = f"board.registerStory(Story({when}, [], name='two'))"
    ok = verdict_of(loops_cfg, tmp_path / "ok", "StoryActivated('two', at_least=2)", story)
    assert ok["passed"] and ok["actual"] == "2 activations", ok
    more = verdict_of(loops_cfg, tmp_path / "more", "StoryActivated('two', at_least=3)", story)
    assert not more["passed"] and more["expected"] == ">= 3 activations", more


def test_custom_criterion_reads_events_and_statistics(loops_cfg: Path, tmp_path: Path) -> None:
    body = """
    class Recorder(Effect):
        def apply(self, vehicle):
            board.record('seen', 1.0, vehicle=vehicle.id)
        def remove(self, vehicle):
            pass

    class FewActivations(Criterion):
        def __init__(self, most):
            super().__init__()
            self.most = most
        def evaluate(self, run):
            n = sum(1 for e in run.events if e['type'] == 'activate')
            seen = run.statistics['seen']['count']
            return (n <= self.most and seen == n, f'{n} activations, {seen:g} recorded', f'<= {self.most}')

    board.registerStory(Story(AndCondition(TimeCondition(10), CarSetCondition(['veh01', 'veh02', 'veh03'])),
                              [Recorder()], name='three'))
    board.registerCriterion(FewActivations(3), name='at most three')
    board.registerCriterion(FewActivations(2))
    """

    result, summary, junit = run_criteria(loops_cfg, tmp_path, textwrap.indent(textwrap.dedent(body), "    "))
    assert result.returncode == 3, result.stderr
    first, second = summary["criteria"]
    assert first == {"name": "at most three", "passed": True, "actual": "3 activations, 3 recorded", "expected": "<= 3"}
    assert second["name"] == "FewActivations()" and not second["passed"]
    cases = junit.findall("testsuite/testcase")
    assert [c.get("name") for c in cases] == ["at most three", "FewActivations()"]
    assert cases[0].find("failure") is None and cases[1].find("failure") is not None


def test_check_lists_the_criteria(loops_cfg: Path, tmp_path: Path) -> None:
    import subprocess

    from sbsim.runner import executable

    story = write_story(
        tmp_path,
        HEADER + "def createStories(board):\n    board.registerCriterion(NoCollision())\n"
        "    board.registerCriterion(MaxSpeed(20, vehicles=['a', 'b']), name='slow')\n",
    )
    done = subprocess.run(
        [str(executable()), "check", "--sumocfg", str(loops_cfg), "--story", str(story)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert "criterion 'NoCollision()'" in done.stdout.splitlines()
    assert "criterion 'slow'" in done.stdout.splitlines()


def test_a_run_without_criteria_has_no_verdict(loops_cfg: Path, tmp_path: Path) -> None:
    result, summary, junit = run_criteria(loops_cfg, tmp_path, "    pass\n", end=5.0)
    assert result.returncode == 0
    assert summary["criteria"] == [] and summary["verdict"] is None
    assert junit.find("testsuite").get("tests") == "0"


def test_junit_is_well_formed_whatever_the_names_and_values_hold(loops_cfg: Path, tmp_path: Path) -> None:
    # XML 1.0 forbids most control characters even as references: they are written as visible escapes.
    body = """
    class Odd(Criterion):
        def evaluate(self, run):
            return (False, "bell\\x07 <b>&\\ttab", "nul\\x00 \\ufffe")

    board.registerCriterion(Odd(), name="odd\\x01\\x1b name\\ttab")
    """
    result, summary, junit = run_criteria(loops_cfg, tmp_path, textwrap.indent(textwrap.dedent(body), "    "), end=5.0)
    assert result.returncode == 3
    assert summary["criteria"][0]["name"] == "odd\x01\x1b name\ttab"
    [case] = junit.findall("testsuite/testcase")
    # A tab stays (XML reads one in an attribute as a space; in an element's text it stays a tab).
    assert case.get("name") == "odd\\x01\\x1b name tab"
    failure = case.find("failure")
    assert failure is not None
    assert failure.text == "actual: bell\\x07 <b>&\ttab; expected: nul\\x00 \\ufffe"


def test_warned_before_equipped_only_judges_the_equipped(tmp_path: Path) -> None:
    # Half the vehicles equipped (seed 2 equips the crash car, so its DENM goes out): the unequipped
    # never hear it, so judging everyone fails on them alone, and judging the equipped passes.
    body = "".join(
        f"    {line}\n"
        for line in [
            *ACCIDENT_STORY.splitlines(),
            f"board.registerCriterion(WarnedBefore({AT_THE_CRASH}, cause=2, since=40, until=160), name='all')",
            f"board.registerCriterion(WarnedBefore({AT_THE_CRASH}, cause=2, since=40, until=160, "
            "equipped_only=True), name='equipped')",
        ]
    )
    events = tmp_path / "events.jsonl"
    extra = ["--services", str(MOTORWAY / "services.xml"), "--penetration", "0.5", "--seed", "2"]
    result, summary, _ = run_criteria(
        MOTORWAY / "motorway.sumocfg", tmp_path, body, None, [*extra, "--events", str(events)]
    )
    assert result.returncode == 3, result.stderr
    everyone, equipped = summary["criteria"]
    assert equipped["passed"] and equipped["actual"].startswith("0 of "), equipped
    judged = int(equipped["actual"].split()[2])
    assert not everyone["passed"], everyone
    unwarned, of = (int(everyone["actual"].split()[k]) for k in (0, 2))
    # Exactly the unequipped were unwarned: those judged among everyone but not among the equipped.
    assert judged > 20 and unwarned == of - judged > 20, (everyone, equipped)
    named = everyone["actual"].split("(")[1].split(")")[0].split(" and ")[0].split(", ")
    logged = {e["vehicle"] for e in read_events(events) if e["type"] == "equipped"}
    assert "crash" in logged and not set(named) & logged, (named, sorted(logged)[:10])
