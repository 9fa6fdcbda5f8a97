"""OpenSCENARIO traffic signals on SUMO traffic lights: TrafficSignalCondition (a light, a link, words,
lamps), TrafficSignalControllerCondition (a phase by name), TrafficSignalStateAction (a light held from
then on: the entity stops), TrafficSignalControllerAction (the programme jumps to a phase), names and
states the network lacks (exit 2), OpenDRIVE signal ids as netconvert keeps them, the same on the story
API (a kept hold), and a MiscObject as an obstacle. The network: a junction "B" with a traffic light
(netconvert, from nodes, edges and a programme written here); the expected times are worked out in each
scenario's comment (or the test's, for a scenario it edits)."""

from __future__ import annotations

import math
import subprocess
from pathlib import Path

import pytest
from sbsim.events import read_events
from sbsim.runner import run
from sbsim_helpers import assert_bad_input
from test_openscenario import run_xosc, scenario, starts

NODES = """<nodes>
  <node id="A" x="0" y="0"/>
  <node id="B" x="500" y="0" type="traffic_light"/>
  <node id="C" x="1000" y="0"/>
  <node id="N" x="500" y="300"/>
  <node id="S" x="500" y="-300"/>
</nodes>
"""
EDGES = """<edges>
  <edge id="AB" from="A" to="B" numLanes="1" speed="13.89"/>
  <edge id="BC" from="B" to="C" numLanes="1" speed="13.89"/>
  <edge id="NB" from="N" to="B" numLanes="1" speed="13.89"/>
  <edge id="BS" from="B" to="S" numLanes="1" speed="13.89"/>
</edges>
"""
# Links (netconvert's order): 0 NB->BS, 1 NB->BC, 2 AB->BS, 3 AB->BC.
PROGRAMME = """<tlLogics>
  <tlLogic id="B" type="static" programID="0" offset="0">
    <phase duration="10" state="GGrr" name="northGreen"/>
    <phase duration="3" state="yyrr" name="northYellow"/>
    <phase duration="10" state="rrGG" name="eastGreen"/>
    <phase duration="3" state="rryy" name="eastYellow"/>
  </tlLogic>
</tlLogics>
"""


def sumo_tool(name: str) -> str:
    import sumo

    return str(Path(sumo.SUMO_HOME) / "bin" / name)


@pytest.fixture(scope="module")
def signal_net(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The junction with its light and a sumocfg (0.1 s steps, 60 s)."""
    out = tmp_path_factory.mktemp("xosc-signal")
    (out / "b.nod.xml").write_text(NODES)
    (out / "b.edg.xml").write_text(EDGES)
    (out / "b.tll.xml").write_text(PROGRAMME)
    subprocess.run(
        [
            sumo_tool("netconvert"),
            "-n",
            str(out / "b.nod.xml"),
            "-e",
            str(out / "b.edg.xml"),
            "-i",
            str(out / "b.tll.xml"),
            "--no-turnarounds",
            "-o",
            str(out / "b.net.xml"),
        ],
        check=True,
        capture_output=True,
    )
    (out / "b.sumocfg").write_text(
        '<configuration><input><net-file value="b.net.xml"/></input>'
        '<time><begin value="0"/><end value="60"/><step-length value="0.1"/></time></configuration>\n'
    )
    return out / "b.sumocfg"


def test_conditions_fire_when_the_programme_shows_the_state(signal_net: Path, tmp_path: Path) -> None:
    events, _ = run_xosc(scenario(tmp_path, "signal-condition.xosc"), sumocfg=signal_net)
    assert starts(events, "S/A/Whole") == [0.2, 26.1], "GGrr at the start, then the next cycle"
    assert starts(events, "S/A/Green") == [13.1], "link 3 turns green at 13"
    assert starts(events, "S/A/Yellow") == [23.1], "phase eastYellow from 23"
    assert starts(events, "S/A/Lamps") == [23.1], "off;on;off is yellow"


def test_a_state_action_holds_the_light_and_the_entity_stops(signal_net: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "signal-action.xosc")
    events, fcd = run_xosc(xosc, sumocfg=signal_net)
    assert starts(events, "S/A/Red (world)") == [5.1]
    assert starts(events, "S/A/Held") == [], "link 0 stays green: the light is held at GGrr"
    assert fcd.lane["Ego"][40.0] == "AB_0" and fcd.speed["Ego"][40.0] == pytest.approx(0.0)
    # Without the action the programme runs and Ego passes in link 3's green.
    events, fcd = run_xosc(xosc, "--param", "At=500", sumocfg=signal_net)
    assert starts(events, "S/A/Red (world)") == []
    assert starts(events, "S/A/Held") == [10.1]
    assert fcd.lane["Ego"][40.0] == "BC_0"
    # The whole light red: link 0 too, seen the step after the action.
    events, fcd = run_xosc(xosc, "--param", "Signal=B", "--param", "State=rrrr", sumocfg=signal_net)
    assert starts(events, "S/A/Held") == [5.2]
    assert fcd.lane["Ego"][40.0] == "AB_0" and fcd.speed["Ego"][40.0] == pytest.approx(0.0)


def test_check_prints_the_signal_conditions_and_effects(signal_net: Path, tmp_path: Path) -> None:
    result = run(signal_net, extra=["check", "--scenario", str(scenario(tmp_path, "signal-condition.xosc"))])
    assert result.returncode == 0, result.stderr
    assert "TrafficSignalCondition('B' shows 'GGrr')" in result.stdout
    assert "TrafficSignalCondition('B' link 3 shows 'G')" in result.stdout
    assert "TrafficSignalCondition('B' shows 'rryy')" in result.stdout, "the phase eastYellow's state"
    result = run(signal_net, extra=["check", "--scenario", str(scenario(tmp_path / "b", "signal-action.xosc"))])
    assert result.returncode == 0, result.stderr
    assert "TrafficLightEffect('B', 'r', link 3, kept)" in result.stdout


@pytest.mark.parametrize(
    ("old", "new", "needles"),
    [
        ('name="B:3" state="green"', 'name="Z" state="green"', ["no traffic signal 'Z'", "(B)"]),
        ('name="B:3" state="green"', 'name="B:7" state="green"', ["traffic light 'B' has no link '7'"]),
        ('name="B:3" state="green"', 'name="B:3" state="purple"', ["state 'purple' is none of"]),
        ('name="B" state="GGrr"', 'name="B" state="GGr"', ["state 'GGr' is not a state of traffic light 'B'"]),
        ('phase="eastYellow"', 'phase="west"', ["traffic light 'B' has no phase 'west'", "eastYellow"]),
        ('trafficSignalControllerRef="B"', 'trafficSignalControllerRef="Q"', ["no traffic light 'Q'"]),
    ],
)
def test_names_and_states_the_network_lacks_are_one_line(
    signal_net: Path, tmp_path: Path, old: str, new: str, needles: list[str]
) -> None:
    xosc = scenario(tmp_path, "signal-condition.xosc")
    text = xosc.read_text()
    assert old in text
    xosc.write_text(text.replace(old, new, 1))
    for command in (["check", "--scenario", str(xosc)], ["--scenario", str(xosc)]):
        assert_bad_input(run(signal_net, extra=command, timeout=120), f"{xosc}:", *needles)


def test_a_controller_action_switches_the_programme_to_the_phase(signal_net: Path, tmp_path: Path) -> None:
    """signal-action.xosc with a TrafficSignalControllerAction to phase eastGreen at t > 5 instead: SUMO's
    programme jumps to eastGreen at 5.1 for its full 10 s (eastYellow from 15.1, northGreen 18.1 to 28.1,
    eastGreen again from 31.1). Link 0 stops being green at 5.1, seen at 5.2 (Held). Ego reaches the line
    at about t = 19, in northGreen: it stands on AB at t = 25 (in the programme it passed in eastGreen,
    13-23) and passes in the next eastGreen, on BC by t = 40."""
    xosc = scenario(tmp_path, "signal-action.xosc")
    xosc.write_text(
        xosc.read_text().replace(
            '<TrafficSignalStateAction name="$Signal" state="$State"/>',
            '<TrafficSignalControllerAction trafficSignalControllerRef="B" phase="eastGreen"/>',
        )
    )
    events, fcd = run_xosc(xosc, sumocfg=signal_net)
    assert starts(events, "S/A/Red (world)") == [5.1]
    assert starts(events, "S/A/Held") == [5.2]
    assert fcd.lane["Ego"][25.0] == "AB_0" and fcd.speed["Ego"][25.0] == pytest.approx(0.0)
    assert fcd.lane["Ego"][40.0] == "BC_0"
    check = run(signal_net, extra=["check", "--scenario", str(xosc)], timeout=120)
    assert check.returncode == 0, check.stderr
    assert "TrafficLightPhaseEffect('B', phase 2)" in check.stdout
    xosc.write_text(xosc.read_text().replace('phase="eastGreen"', 'phase="red"'))
    assert_bad_input(run(signal_net, extra=["--scenario", str(xosc)], timeout=120), "has no phase 'red'")


def test_declared_controllers_are_unsupported(signal_net: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "signal-action.xosc")
    xosc.write_text(
        xosc.read_text().replace(
            "<RoadNetwork/>",
            '<RoadNetwork><TrafficSignals><TrafficSignalController name="B"><Phase name="p" duration="5">'
            '<TrafficSignalState trafficSignalId="B:3" state="red"/></Phase></TrafficSignalController>'
            "</TrafficSignals></RoadNetwork>",
        )
    )
    line = assert_bad_input(run(signal_net, extra=["--scenario", str(xosc)], timeout=120), "1 unsupported")
    assert "<TrafficSignals>" in line and "declared traffic signal controllers" in line


def test_opendrive_signal_ids_name_the_links_netconvert_gave_them(tmp_path: Path) -> None:
    """A four-way OpenDRIVE junction (scenariogeneration) with a signal on each road: netconvert names the
    light for the junction (100) and records each link's OpenDRIVE signal (linkSignalID:<link>)."""
    from scenariogeneration import xodr
    from storyboard.openscenario.errors import ScenarioError
    from storyboard.openscenario.network import Network
    from storyboard.openscenario.signals import signal_links, signal_state

    roads = []
    for i in range(4):
        road = xodr.create_road([xodr.Line(100)], id=i, left_lanes=1, right_lanes=1)
        road.add_signal(
            xodr.Signal(s=98.0, t=-4, country="DEU", Type="1000001", id=str(200 + i), dynamic=xodr.Dynamic.yes)
        )
        roads.append(road)
    junction = xodr.CommonJunctionCreator(100, "cross")
    for i, road in enumerate(roads):
        a = i * math.pi / 2
        junction.add_incoming_road_cartesian_geometry(
            road, 40 * math.cos(a), 40 * math.sin(a), a + math.pi, "successor"
        )
    junction.add_connection(road_one_id=0, road_two_id=2)
    junction.add_connection(road_one_id=1, road_two_id=3)
    odr = xodr.OpenDrive("cross")
    for i, road in enumerate(roads):
        a = i * math.pi / 2
        road.planview.set_start_point(140 * math.cos(a), 140 * math.sin(a), a + math.pi)
        odr.add_road(road)
    odr.add_junction_creator(junction)
    odr.adjust_roads_and_lanes()
    odr.write_xml(str(tmp_path / "cross.xodr"))
    net_file = tmp_path / "cross.net.xml"
    subprocess.run(
        [sumo_tool("netconvert"), "--opendrive-files", str(tmp_path / "cross.xodr"), "--output.original-names"]
        + ["-o", str(net_file)],
        check=True,
        capture_output=True,
    )
    net = Network.read(net_file)
    assert list(net.lights) == ["100"]
    light = net.lights["100"]
    # Each signal is one link; every link has one signal.
    assert sorted(i for _, links in net.signals.values() for i in links) == list(range(light.links))
    signal, (tls, links) = next(iter(sorted(net.signals.items())))
    assert signal_links(net, signal, "here") == (tls, links) == ("100", links)
    assert signal_state(net, "100", links, "off;off;on", "here") == "G"
    assert signal_links(net, "100:0", "here") == ("100", [0])
    with pytest.raises(ScenarioError, match="no traffic signal '999'"):
        signal_links(net, "999", "here")


@pytest.mark.parametrize("hold", [False, True])
def test_a_story_on_a_link_and_a_kept_hold(signal_net: Path, tmp_path: Path, hold: bool) -> None:
    """The Python story API on the same light: link 3 is green 13-23 and 39-49 (a 26 s cycle), seen 0.1 s
    later; a kept red on link 3 at t = 30 (the light shows GGrr then) holds it past its story's end
    (31 s): link 3 never turns green again."""
    from sbsim_helpers import write_story

    effect = "[sb.TrafficLightEffect('B', 'r', links=[3], keep=True)]" if hold else "[]"
    story = write_story(
        tmp_path,
        f"""
        import storyboard as sb

        def createStories(board):
            board.registerStory(sb.WorldStory(sb.TrafficSignalCondition('B', 'G', links=[3]), [], name='green'))
            board.registerStory(sb.WorldStory(sb.TimeCondition(30, 31), {effect}, name='hold'))
        """,
    )
    # A vehicle keeps the run going (it ends when SUMO expects no more).
    (tmp_path / "v.rou.xml").write_text(
        '<routes><vehicle id="v" depart="0"><route edges="AB BC"/></vehicle></routes>\n'
    )
    cfg = tmp_path / "v.sumocfg"
    cfg.write_text(
        f'<configuration><input><net-file value="{signal_net.parent / "b.net.xml"}"/>'
        '<route-files value="v.rou.xml"/></input>'
        '<time><begin value="0"/><end value="60"/><step-length value="0.1"/></time></configuration>\n'
    )
    events_file = tmp_path / "events.jsonl"
    result = run(cfg, story=story, events=events_file, timeout=120)
    assert result.returncode == 0, result.stderr
    events = read_events(events_file)
    assert starts(events, "green") == ([13.1] if hold else [13.1, 39.1])
    ends = [e["t"] for e in events if e["type"] == "deactivate" and e["story"] == "green"]
    assert ends == ([23.1] if hold else [23.1, 49.1])


def test_a_misc_object_is_an_obstacle_the_entity_stops_behind(signal_net: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "obstacle.xosc"), sumocfg=signal_net)
    assert starts(events, "Init/Box (obstacle)") == [0.2], "from when it runs (spawned at the first step)"
    box = {round(x, 3) for x, _ in fcd.pos["Box"].values()}
    assert box == {200.0}, "held at speed 0 where it was put"
    assert max(fcd.speed["Box"].values()) == 0.0
    assert fcd.speed["Ego"][30.0] == pytest.approx(0.0)
    ego_x = fcd.pos["Ego"][30.0][0]
    assert 180.0 < ego_x <= 193.5 + 1e-6, "behind the box's back (196) by at least SUMO's minGap"
    assert fcd.lane["Ego"][30.0] == "AB_0"
