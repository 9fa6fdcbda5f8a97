"""World stories (WorldStory with CloseRoadEffect, SpawnEffect, TrafficLightEffect) on the generated
grid, checked against SUMO's own FCD output: nobody enters a closed road, a spawned vehicle exists
from its activation on, a held traffic light lets nobody cross; and the errors scripts can make."""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest
from sbsim.runner import read_events, run
from sbsim_helpers import STORIES, StoryRun, read_fcd, run_story

CLOSED = ("B1C1", "C1B1")
CLOSE_FROM, CLOSE_TO = 60, 180


def _on(run_: StoryRun, edges: tuple[str, ...], t: float) -> set[str]:
    """Vehicles on a lane of `edges` at sbsim time t (FCD)."""
    assert run_.fcd is not None
    return {v for v, lanes in run_.fcd.lane.items() if lanes.get(t, "").rsplit("_", 1)[0] in edges}


@pytest.fixture(scope="module")
def closure_run(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    story = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.WorldStory(sb.TimeCondition({CLOSE_FROM}, {CLOSE_TO}),
                                              [sb.CloseRoadEffect({list(CLOSED)!r})], "bridge"))
    """
    return run_story(trips_cfg, story, tmp_path_factory.mktemp("closure"), end=300, fcd=True)


def test_world_story_logs_with_vehicle_null(closure_run: StoryRun) -> None:
    assert closure_run.of(story="bridge") == [
        {"t": CLOSE_FROM, "type": "activate", "story": "bridge", "vehicle": None},
        {"t": CLOSE_TO + 1, "type": "deactivate", "story": "bridge", "vehicle": None, "reason": "condition"},
    ]
    assert "activations bridge: 1" in closure_run.result.stdout


def test_nobody_enters_a_closed_road_and_traffic_returns_after(closure_run: StoryRun) -> None:
    fcd = closure_run.fcd
    assert fcd is not None
    times = sorted(fcd.times)
    before = [t for t in times if t <= CLOSE_FROM]
    during = [t for t in times if CLOSE_FROM < t <= CLOSE_TO]
    after = [t for t in times if t > CLOSE_TO + 1]
    assert any(_on(closure_run, CLOSED, t) for t in before), "the road is used before the closure"
    # Those on it when it closed drive off; nobody else is ever on it while it is closed.
    on_at_close = _on(closure_run, CLOSED, CLOSE_FROM)
    for t in during:
        assert _on(closure_run, CLOSED, t) <= on_at_close, t
    assert not any(_on(closure_run, CLOSED, t) for t in during[30:]), "the ones on it left"
    assert any(_on(closure_run, CLOSED, t) for t in after), "traffic drives on it again"


def test_vehicles_that_cannot_avoid_the_closure_are_removed_before_departing(closure_run: StoryRun) -> None:
    fcd = closure_run.fcd
    assert fcd is not None
    removed = re.findall(r"vehicle '([^']+)' removed before it departed", closure_run.result.stderr)
    for v in removed:
        assert v not in fcd.speed, f"{v} was removed but drove"


def test_spawned_vehicle_exists_from_activation_and_a_story_stops_it(
    trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    story = """
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.WorldStory(sb.TimeCondition(50), [
                sb.SpawnEffect("spawned", from_edge="A0B0", to_edge="D3C3", lane=0, position=5, speed=3),
                sb.SpawnEffect("routed", route=["A0A1", "A1A2"], type="truck"),
            ], "spawn"))
            board.registerStory(sb.Story(sb.AndCondition(sb.CarSetCondition(["spawned"]), sb.TimeCondition(80)),
                                         [sb.StopEffect()], "stop"))
    """
    result = run_story(trips_cfg, story, tmp_path_factory.mktemp("spawn"), end=200, fcd=True)
    fcd = result.fcd
    assert fcd is not None
    assert result.of(story="spawn", type="activate") == [
        {"t": 50, "type": "activate", "story": "spawn", "vehicle": None}
    ]
    # Added at t=50, inserted by the step from 50 to 51 (FCD labels it 50, sbsim time 51).
    assert min(fcd.speed["spawned"]) == 51
    assert fcd.lane["spawned"][51] == "A0B0_0"
    assert fcd.speed["spawned"][51] == pytest.approx(3, abs=1.5)
    assert fcd.type["routed"][51] == "truck"
    assert fcd.lane["routed"][51].startswith("A0A1_")
    assert result.activated("stop") == ["spawned"]
    standing = [t for t, v in fcd.speeds("spawned", 80).items() if v == 0]
    assert standing and max(fcd.speeds("spawned")) == max(standing), "it stops and stays stopped"
    assert len(result.of(story="spawn")) == 1, "spawned once, never deactivated"


def _light(trips_cfg: Path) -> tuple[str, int, set[str]]:
    """A traffic light of the grid, its number of signals and the edges coming into it."""
    net = ET.parse(trips_cfg.parent / "net.net.xml").getroot()
    tls = sorted(net.iter("tlLogic"), key=lambda e: e.attrib["id"])
    light = next(t for t in tls if t.attrib["id"] == "B1")
    signals = len(next(light.iter("phase")).attrib["state"])
    incoming = {e.attrib["id"] for e in net.iter("edge") if e.attrib.get("to") == "B1"}
    return "B1", signals, incoming


def test_traffic_light_holds_its_state_then_its_programme_resumes(
    trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    tls, signals, incoming = _light(trips_cfg)
    story = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.WorldStory(sb.TimeCondition(60, 160),
                                              [sb.TrafficLightEffect({tls!r}, {"r" * signals!r})], "red"))
    """
    result = run_story(trips_cfg, story, tmp_path_factory.mktemp("tls"), end=300, fcd=True)
    fcd = result.fcd
    assert fcd is not None

    def crossing(t: float) -> set[str]:
        return {v for v, lanes in fcd.lane.items() if lanes.get(t, "").startswith(f":{tls}_")}

    held = [t for t in fcd.times if 70 <= t <= 161]
    assert not any(crossing(t) for t in held), "all red: nobody crosses"
    waiting = {
        v
        for t in held
        for v, lanes in fcd.lane.items()
        if lanes.get(t, "").rsplit("_", 1)[0] in incoming and fcd.speed[v][t] == 0
    }
    assert waiting, "vehicles wait at the red light"
    assert any(crossing(t) for t in fcd.times if 0 < t < 60), "the junction is used before"
    assert any(crossing(t) for t in fcd.times if t > 165), "its programme runs again"


@pytest.mark.parametrize(
    ("body", "needle"),
    [
        ('sb.Story(sb.TimeCondition(1), [sb.CloseRoadEffect("B1C1")])', "is a world effect: put it in a WorldStory"),
        ("sb.WorldStory(sb.TimeCondition(1), [sb.StopEffect()])", "per-vehicle effects go in a Story"),
        (
            "sb.WorldStory(sb.AndCondition(sb.TimeCondition(1), sb.SpeedConditionGreater(3)), [])",
            "WorldStory conditions look at time only",
        ),
        (
            'sb.WorldStory(sb.TimeCondition(5), [sb.CloseRoadEffect(["B1C1", "nowhere"])], "c")',
            "story 'c': CloseRoadEffect names edges the network does not have: nowhere",
        ),
        (
            'sb.WorldStory(sb.TimeCondition(5), [sb.TrafficLightEffect("nolight", "r")], "t")',
            "story 't': TrafficLightEffect names traffic lights the network does not have: nolight",
        ),
        (
            'sb.WorldStory(sb.TimeCondition(5), [sb.TrafficLightEffect("B1", "rr")], "t")',
            "has 2 signals, traffic light 'B1' controls",
        ),
        (
            'sb.WorldStory(sb.TimeCondition(5), [sb.SpawnEffect("veh0", route=["A0B0"])], "s")',
            "story 's': SpawnEffect at t=5 s: vehicle 'veh0' exists already",
        ),
        (
            'sb.WorldStory(sb.TimeCondition(5), [sb.SpawnEffect("x", from_edge="A0B0", to_edge="nowhere")], "s")',
            "story 's': SpawnEffect names edges the network does not have: nowhere",
        ),
    ],
)
def test_script_mistakes_are_clear_errors(trips_cfg: Path, tmp_path: Path, body: str, needle: str) -> None:
    story = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory({body})
    """
    result = run_story(trips_cfg, story, tmp_path, end=20, check=False)
    assert result.returncode == 2, result.result.stderr
    assert needle in result.result.stderr
    assert len(result.result.stderr.strip().splitlines()) <= 12


def test_check_lists_world_stories(trips_cfg: Path, tmp_path: Path) -> None:
    story = tmp_path / "story.py"
    story.write_text(
        "import storyboard as sb\n"
        "def createStories(board):\n"
        "    board.registerStory(sb.WorldStory(sb.TimeCondition(5, 9), [sb.CloseRoadEffect(['B1C1', 'C1B1'])], 'w'))\n",
        encoding="utf-8",
    )
    result = run(trips_cfg, story=story, extra=["check"], timeout=120)
    assert result.returncode == 0, result.stderr
    assert (
        "story 'w'\n  world story: acts on the network\n  TimeCondition(5 s, 9 s)\n  → CloseRoadEffect(B1C1, C1B1)\n"
        in (result.stdout)
    )
    as_json = run(trips_cfg, story=story, extra=["check", "--json"], timeout=120)
    assert [s["world"] for s in json.loads(as_json.stdout)["stories"]] == [True]


def run_bundled(name: str, tmp_path: Path) -> tuple[Any, Path, Path]:
    """Runs stories/<name> as it is, with its event log and SUMO's FCD output in tmp_path."""
    folder = STORIES / name
    events, fcd_path = tmp_path / f"{name}.jsonl", tmp_path / f"{name}.fcd.xml"
    result = run(
        folder / f"{name}.sumocfg",
        story=folder / "story.py",
        events=events,
        sumo_options=[f"--fcd-output {fcd_path}"],
        timeout=120,
    )
    return result, events, fcd_path


def test_bridge_closure_story_runs_as_its_readme_says(tmp_path: Path) -> None:
    result, events, fcd_path = run_bundled("bridge-closure", tmp_path)
    assert result.returncode == 0, result.stderr
    assert "activations bridge-closed: 1" in result.stdout
    lines = [e for e in read_events(events) if e["story"] == "bridge-closed"]
    assert [(e["t"], e["type"], e["vehicle"]) for e in lines] == [(120, "activate", None), (361, "deactivate", None)]
    fcd = read_fcd(fcd_path)
    bridge = {v: lanes for v, lanes in fcd.lane.items() if any(lane.startswith("bridge_") for lane in lanes.values())}
    on_bridge = {t: {v for v, lanes in bridge.items() if lanes.get(t, "").startswith("bridge_")} for t in fcd.times}
    assert on_bridge[120] and all(on_bridge[t] <= on_bridge[120] for t in fcd.times if 120 <= t <= 361)
    assert not any(on_bridge[t] for t in fcd.times if 160 <= t <= 361)
    assert any(on_bridge[t] for t in fcd.times if t > 361)
    assert any(e["story"] == "detour" for e in read_events(events))


def test_broken_down_truck_story_runs_as_its_readme_says(tmp_path: Path) -> None:
    result, events, fcd_path = run_bundled("broken-down-truck", tmp_path)
    assert result.returncode == 0, result.stderr
    log = read_events(events)
    assert [e for e in log if e["story"] == "breakdown"] == [
        {"t": 300, "type": "activate", "story": "breakdown", "vehicle": None}
    ]
    fcd = read_fcd(fcd_path)
    truck = fcd.speeds("broken-truck")
    assert min(truck) > 300 and set(truck.values()) == {0.0}
    assert set(fcd.lane["broken-truck"].values()) == {"motorway_0"}
    warnings = [e for e in log if e["story"] == "warning" and e["type"] == "signal"]
    assert warnings and all(e["others"] == ["broken-truck"] for e in warnings)
    assert all(e["t"] >= min(truck) for e in warnings)
