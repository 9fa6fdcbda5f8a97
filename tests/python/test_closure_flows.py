"""A closure and the vehicles SUMO makes in the step they depart (flows, with from/to or a fixed
route): on a generated 3 x 3 grid with randomTrips flows (fixed seeds), closing a flow's first
edge, its last edge, and every edge of the network in turn ends with exit 0, and every vehicle
whose trip the closure cut is removed before it moves, with one warning line each (README,
"World effects": CloseRoadEffect)."""

from __future__ import annotations

import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import pytest
from sbsim.scenarios.grid import make_grid
from sbsim.sumo import sumo_home
from sbsim_helpers import STORIES, StoryRun, assert_no_crash, run_story

CLOSE_FROM, CLOSE_TO = 10, 70  # the closure acts on vehicles SUMO inserts at 10 s .. 70 s
END = 100.0

#: sbsim's line for a vehicle it took out in the step SUMO made and inserted it.
REMOVED_AT_INSERTION = re.compile(r"^sbsim: warning: t=\S+ s: vehicle '([^']+)' removed in the step SUMO made", re.M)
#: sbsim's line for a loaded vehicle it took out before it departed.
REMOVED_WAITING = re.compile(r"^sbsim: warning: t=\S+ s: vehicle '([^']+)' removed before it departed: its trip", re.M)
#: sbsim's line for a vehicle SUMO dropped in the step that made it (its first edge closed).
DROPPED_SBSIM = re.compile(
    r"^sbsim: warning: t=\S+ s: vehicle '([^']+)' removed before it departed: SUMO dropped", re.M
)
#: SUMO's line for a vehicle it dropped because no lane of its first edge lets it on.
DROPPED = re.compile(r"^Warning: Vehicle '([^']+)' is not allowed to depart on any lane of edge '([^']+)'\.", re.M)


@dataclass(frozen=True)
class Flow:
    id: str
    begin: float
    end: float
    period: float
    first: str
    last: str

    def vehicles_between(self, start: float, stop: float) -> set[str]:
        """The flow's vehicles SUMO makes with a departure time in [start, stop]."""
        out = set()
        k = 0
        while self.begin + k * self.period < self.end:
            if start <= self.begin + k * self.period <= stop:
                out.add(f"{self.id}.{k}")
            k += 1
        return out


def _random_flows(net: Path, out: Path, prefix: str, seed: int, routed: bool) -> None:
    args = [
        sys.executable,
        str(sumo_home() / "tools" / "randomTrips.py"),
        "-n",
        str(net),
        "--seed",
        str(seed),
        "--begin",
        "0",
        "--end",
        "120",
        "--period",
        "2",
        "--flows",
        "6",
        "--prefix",
        prefix,
        "-o",
        str(out.with_suffix(".trips.xml") if routed else out),
    ]
    if routed:
        args += ["-r", str(out)]  # duarouter gives each flow its fixed route
    subprocess.run(args, cwd=out.parent, check=True, capture_output=True)


def _flows(path: Path) -> list[Flow]:
    flows = []
    for f in ET.parse(path).getroot().iter("flow"):
        route = f.find("route")
        edges = route.attrib["edges"].split() if route is not None else [f.attrib["from"], f.attrib["to"]]
        flows.append(
            Flow(
                f.attrib["id"],
                float(f.attrib["begin"]),
                float(f.attrib["end"]),
                float(f.attrib["period"]),
                edges[0],
                edges[-1],
            )
        )
    return flows


@pytest.fixture(scope="module")
def flow_net(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A 3 x 3 grid and two flow files: trip flows (from/to, routed by SUMO at insertion) and
    flows with fixed routes (duarouter's), six each, a vehicle every 12 s per flow."""
    out = tmp_path_factory.mktemp("closure-flows")
    make_grid(out, grid=3, end=END, seed=7)
    _random_flows(out / "net.net.xml", out / "trips.rou.xml", "t", 7, routed=False)
    _random_flows(out / "net.net.xml", out / "routed.rou.xml", "r", 8, routed=True)
    (out / "flows.sumocfg").write_text(
        """<configuration>
    <input>
        <net-file value="net.net.xml"/>
        <route-files value="trips.rou.xml,routed.rou.xml"/>
    </input>
    <time><begin value="0"/><end value="100"/></time>
    <report><no-step-log value="true"/></report>
</configuration>
""",
        encoding="utf-8",
    )
    return out / "flows.sumocfg"


def _all_flows(cfg: Path) -> list[Flow]:
    return _flows(cfg.parent / "trips.rou.xml") + _flows(cfg.parent / "routed.rou.xml")


def _close(cfg: Path, edge: str, directory: Path, fcd: bool = False) -> StoryRun:
    story = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.WorldStory(sb.TimeCondition({CLOSE_FROM}, {CLOSE_TO}),
                                              [sb.CloseRoadEffect([{edge!r}])], "closure"))
    """
    # --verbose: every one of SUMO's warnings on stderr, not only the first of each kind.
    return run_story(cfg, story, directory, end=END, fcd=fcd, extra=("--verbose",))


def _moved(run_: StoryRun, vehicle: str) -> bool:
    assert run_.fcd is not None
    return len(set(run_.fcd.pos.get(vehicle, {}).values())) > 1 or len(run_.fcd.pos.get(vehicle, {})) > 1


def _one_each(ids: list[str]) -> set[str]:
    assert len(ids) == len(set(ids)), f"a vehicle warned about twice: {sorted(ids)}"
    return set(ids)


def test_closing_the_first_edge_of_waiting_flow_vehicles(flow_net: Path, tmp_path: Path) -> None:
    flows = _all_flows(flow_net)
    edge = max({f.first for f in flows}, key=lambda e: sum(f.first == e for f in flows))
    expected = set().union(*(f.vehicles_between(CLOSE_FROM, CLOSE_TO) for f in flows if f.first == edge))
    assert expected, "the scenario has flows starting on the edge"
    run_ = _close(flow_net, edge, tmp_path, fcd=True)
    dropped = [v for v, e in DROPPED.findall(run_.result.stderr)]
    assert {e for _, e in DROPPED.findall(run_.result.stderr)} == {edge}
    assert _one_each(dropped) == expected
    assert _one_each(DROPPED_SBSIM.findall(run_.result.stderr)) == expected  # sbsim's own line, once each
    # Others have no way around that edge (a grid's corner): sbsim takes them out, once each.
    stderr = run_.result.stderr
    removed = _one_each(REMOVED_AT_INSERTION.findall(stderr) + REMOVED_WAITING.findall(stderr))
    assert not removed & expected
    assert run_.fcd is not None
    for v in expected:
        assert v not in run_.fcd.pos, f"{v} was dropped yet drove"
    for v in removed:
        assert not _moved(run_, v), f"{v} was removed yet moved"
    # Outside the closure the flows' vehicles depart from that edge as usual.
    after = set().union(*(f.vehicles_between(CLOSE_TO + 1, END - 20) for f in flows if f.first == edge))
    assert after and after <= set(run_.fcd.pos)


def test_closing_the_last_edge_of_waiting_flow_vehicles(flow_net: Path, tmp_path: Path) -> None:
    flows = _all_flows(flow_net)
    # An edge some flows end on and none starts on (those would be dropped instead).
    candidates = {f.last for f in flows} - {f.first for f in flows}
    edge = max(sorted(candidates), key=lambda e: sum(f.last == e for f in flows))
    expected = set().union(*(f.vehicles_between(CLOSE_FROM, CLOSE_TO) for f in flows if f.last == edge))
    assert expected
    run_ = _close(flow_net, edge, tmp_path, fcd=True)
    # SUMO inserts a trip on the route it has, and sbsim takes it out in that step; SUMO cannot
    # insert a vehicle whose fixed route's next edge is closed, so it waits and sbsim takes it out.
    stderr = run_.result.stderr
    removed = _one_each(REMOVED_AT_INSERTION.findall(stderr) + REMOVED_WAITING.findall(stderr))
    assert expected <= removed  # and those with no way around it
    assert not DROPPED.findall(run_.result.stderr)
    for v in removed:
        assert not _moved(run_, v), f"{v} was removed yet moved"
    assert run_.fcd is not None
    after = set().union(*(f.vehicles_between(CLOSE_TO + 1, END - 20) for f in flows if f.last == edge))
    assert after and after <= set(run_.fcd.pos)


def test_closing_every_edge_in_turn(flow_net: Path, tmp_path: Path) -> None:
    net = ET.parse(flow_net.parent / "net.net.xml").getroot()
    edges = sorted(e.attrib["id"] for e in net.iter("edge") if e.attrib.get("function") != "internal")
    assert len(edges) == 24
    flows = _all_flows(flow_net)
    for edge in edges:
        run_ = _close(flow_net, edge, tmp_path / edge)
        assert_no_crash(run_.result)
        stderr = run_.result.stderr
        removed = _one_each(REMOVED_AT_INSERTION.findall(stderr) + REMOVED_WAITING.findall(stderr))
        dropped = _one_each([v for v, _ in DROPPED.findall(stderr)])
        # Every flow vehicle made during the closure on a flow that starts there is dropped by SUMO.
        starting = set().union(*(f.vehicles_between(CLOSE_FROM, CLOSE_TO) for f in flows if f.first == edge))
        assert dropped == starting, edge
        assert _one_each(DROPPED_SBSIM.findall(stderr)) == starting, edge
        ending = set().union(*(f.vehicles_between(CLOSE_FROM, CLOSE_TO) for f in flows if f.last == edge))
        assert ending - starting <= removed, edge
        assert not removed & dropped, edge


@pytest.mark.parametrize(
    "edge",
    ["bridge_e", "bridge_w", "east_in", "east_out", "ebank_n", "ebank_s"]
    + ["south_e", "south_w", "wbank_n", "wbank_s", "west_in", "west_out"],
)
def test_closing_each_edge_of_bridge_closure_under_its_own_trips(edge: str, tmp_path: Path) -> None:
    """The issue's case: stories/bridge-closure's flows (from/to, a car every 8 s each way), one
    edge closed from 120 s to 360 s instead of the bridge."""
    cfg = STORIES / "bridge-closure" / "bridge-closure.sumocfg"
    story = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.WorldStory(sb.TimeCondition(120, 360), [sb.CloseRoadEffect([{edge!r}])], "c"))
    """
    run_ = run_story(cfg, story, tmp_path, end=400, fcd=True, extra=("--verbose",))
    stderr = run_.result.stderr
    removed = _one_each(REMOVED_AT_INSERTION.findall(stderr) + REMOVED_WAITING.findall(stderr))
    dropped = _one_each([v for v, e in DROPPED.findall(stderr)])
    assert {e for _, e in DROPPED.findall(stderr)} <= {edge}
    assert _one_each(DROPPED_SBSIM.findall(stderr)) == dropped
    assert not removed & dropped
    flows = {"eastbound": ("west_in", "east_out", 0.0), "westbound": ("east_in", "west_out", 4.0)}
    for flow, (first, last, begin) in flows.items():
        made = {f"{flow}.{k}" for k in range(63) if 120 <= begin + 8 * k <= 360}
        if edge == first:
            assert made == {v for v in dropped if v.startswith(flow + ".")}
        elif edge == last:
            assert made <= removed
    assert run_.fcd is not None
    for v in dropped:
        assert v not in run_.fcd.pos
    for v in removed:
        assert not _moved(run_, v), f"{v} was removed yet moved"
