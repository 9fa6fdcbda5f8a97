"""GeoNetworking end to end on the disc model: a DENM crosses its destination area in two hops
(contention-based forwarding) to a vehicle the source cannot reach, and goes no further than the
area; a roadside unit outside its DENM's area reaches it by greedy forwarding. With
``--gn-forwarding off`` the same DENMs go one hop.

Vehicles stand (almost) still on a straight road, 280 m apart, with a 300 m radio range: each hears
only its neighbours, so any reception two stations away took a forwarder.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from sbsim.runner import read_message_lines, run
from sbsim.sumo import sumo_binary
from sbsim_helpers import assert_bad_input, assert_no_crash, message_counts, write_story

RANGE = "300"


def road(folder: Path, vehicles: dict[str, float], services: str) -> Path:
    """A straight 2 km road along y = 0 with `vehicles` (id: x) creeping at 0.05 m/s from 0 s."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "r.nod.xml").write_text('<nodes><node id="a" x="0" y="0"/><node id="b" x="2000" y="0"/></nodes>')
    (folder / "r.edg.xml").write_text('<edges><edge id="e" from="a" to="b" numLanes="1" speed="30"/></edges>')
    subprocess.run(
        [str(sumo_binary("netconvert")), "-n", "r.nod.xml", "-e", "r.edg.xml", "-o", "r.net.xml"],
        cwd=folder,
        check=True,
        capture_output=True,
    )
    rows = "\n".join(
        f'<vehicle id="{v}" type="slow" depart="0" route="r" departPos="{x:g}" departSpeed="0"/>'
        for v, x in sorted(vehicles.items(), key=lambda item: item[1])
    )
    (folder / "r.rou.xml").write_text(
        f'<routes><vType id="slow" maxSpeed="0.05" sigma="0" speedDev="0"/><route id="r" edges="e"/>\n{rows}\n</routes>'
    )
    (folder / "services.xml").write_text(services)
    cfg = folder / "r.sumocfg"
    cfg.write_text(
        '<configuration><input><net-file value="r.net.xml"/><route-files value="r.rou.xml"/></input>'
        '<time><step-length value="0.1"/></time><report><no-step-log value="true"/></report></configuration>'
    )
    return cfg


def denm_run(cfg: Path, out: Path, *extra: str, story: Path | None = None) -> tuple[list[dict], str]:
    messages = out / "messages.jsonl"
    result = run(
        cfg,
        story=story,
        end=8.5,  # the last DENM (8 s) has crossed the area by then
        extra=["--services", str(cfg.parent / "services.xml"), "--v2x-range", RANGE, "--messages", str(messages)]
        + list(extra),
        timeout=300,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return read_message_lines(messages), result.stdout


def warned(lines: list[dict]) -> set[str]:
    """Stations whose DENM memory took an event in (a `denm` line with phase `new`)."""
    return {line["station"] for line in lines if line["event"] == "denm" and line["phase"] == "new"}


# The crash car at x = 100 announces a hazard to a 600 m circle around it: hop1 (380) hears it
# directly, hop2 (660) only through hop1, out (940) only through hop2 and lies outside the area.
LINE = {"src": 100.0, "hop1": 380.0, "hop2": 660.0, "out": 940.0}
DEN = (
    '<services><service type="artery.application.DenService" useCases="uc.xml"/></services>',
    '<usecases><usecase type="StoryboardEvent" signal="hazard" cause="3" area="600" interval="1" duration="60">'
    '<filters><name pattern="src"/></filters></usecase></usecases>',
)


@pytest.fixture
def line_scenario(tmp_path: Path) -> tuple[Path, Path]:
    cfg = road(tmp_path / "line", LINE, DEN[0])
    (cfg.parent / "uc.xml").write_text(DEN[1])
    story = write_story(
        tmp_path,
        "from storyboard import *\n"
        "def createStories(board):\n"
        "    hazard = AndCondition(CarSetCondition('src'), TimeCondition(2))\n"
        "    board.registerStory(Story(hazard, [SignalEffect('hazard')], name='hazard'))\n",
    )
    return cfg, story


def test_a_denm_reaches_two_hops_inside_its_area_and_not_beyond(
    tmp_path: Path, line_scenario: tuple[Path, Path]
) -> None:
    cfg, story = line_scenario
    lines, stdout = denm_run(cfg, tmp_path, story=story)
    assert warned(lines) == {"src", "hop1", "hop2"}, "hop2 through hop1; out is outside the area"
    rx = [line for line in lines if line["event"] == "rx" and line["type"] == "DENM"]
    assert all(line["distance"] <= 300 for line in rx), "one radio hop at a time"
    first = {}
    for line in rx:
        first.setdefault(line["station"], line)
    assert (first["hop1"]["sender"], first["hop1"]["hops"], first["hop1"]["source"]) == ("src", 1, "src")
    assert (first["hop2"]["sender"], first["hop2"]["hops"], first["hop2"]["source"]) == ("hop1", 2, "src")
    # out heard hop2's rebroadcast (a radio reception) but took nothing of it.
    assert (first["out"]["sender"], first["out"]["hops"]) == ("hop2", 3)
    # hop1's CBF timer ran 100 ms - 99 ms * 280/1000 = 72.28 ms after it heard src.
    tx = [line for line in lines if line["event"] == "tx" and line["type"] == "DENM"]
    forward = next(line for line in tx if line["station"] == "hop1")
    assert forward["t"] == pytest.approx(first["hop1"]["t"] + 0.07228, abs=2e-4)
    assert (forward["source"], forward["hops"]) == ("src", 2)
    # Every DENM went out once from src and was forwarded once by hop1 and once by hop2; out, outside
    # the area, never forwards (its sender was inside).
    sent, _ = message_counts(stdout)["DENM"]
    per_station = {s: sum(line["station"] == s for line in tx) for s in LINE}
    assert per_station["src"] == sent >= 5
    assert per_station["hop1"] == per_station["hop2"] == sent
    assert per_station["out"] == 0
    assert f"forwarded {2 * sent}" in stdout


def test_without_forwarding_the_denm_goes_one_hop(tmp_path: Path, line_scenario: tuple[Path, Path]) -> None:
    cfg, story = line_scenario
    lines, stdout = denm_run(cfg, tmp_path, "--gn-forwarding", "off", story=story)
    assert warned(lines) == {"src", "hop1"}
    assert {line["station"] for line in lines if line["event"] == "tx" and line["type"] == "DENM"} == {"src"}
    assert "forwarded" not in stdout


def test_a_hop_limit_of_one_is_one_hop(tmp_path: Path, line_scenario: tuple[Path, Path]) -> None:
    cfg, story = line_scenario
    lines, _ = denm_run(cfg, tmp_path, "--param", "gn_hop_limit=1", story=story)
    assert warned(lines) == {"src", "hop1"}


def test_a_unit_outside_its_area_reaches_it_greedily(tmp_path: Path) -> None:
    # A roadside unit at x = 0 announces road works at x = 700 to a 250 m circle (450 ... 950). It
    # hears only a (its CAMs put a in its LDM); a, outside the area, passes the packet on to b, the
    # neighbour nearest to the area's centre; b, inside, passes it up and rebroadcasts it to c.
    cars = {"a": 250.0, "b": 500.0, "c": 760.0}
    services = (
        '<services><service type="artery.application.CaService"/>'
        '<rsu id="works" x="0" y="0"><service type="RsuCaService"/>'
        '<service type="RsuDenService" cause="3" from="3" x="700" y="0" area="250"/></rsu></services>'
    )
    cfg = road(tmp_path, cars, services)
    lines, _ = denm_run(cfg, tmp_path)
    assert warned(lines) == {"works", "b", "c"}
    tx = [line for line in lines if line["event"] == "tx" and line["type"] == "DENM"]
    first = {}
    for line in tx:
        first.setdefault(line["station"], line)
    assert first["works"].get("next_hop") == "a", "unicast to the only neighbour, which has progress"
    assert (first["a"]["next_hop"], first["a"]["hops"]) == ("b", 2)
    assert "next_hop" not in first["b"] and first["b"]["hops"] == 3, "inside the area: broadcast"
    off, _ = denm_run(cfg, tmp_path, "--gn-forwarding", "off")
    assert warned(off) == {"works"}, "one hop reaches only a, outside the area"


@pytest.mark.parametrize(
    ("words", "needle"),
    [
        (["--gn-forwarding", "maybe"], "expects on or off, got 'maybe'"),
        (["--param", "gn_forwarding=7"], "expects on or off, got '7'"),
        (["--gn-hop-limit", "0"], "expects 1 to 255, got '0'"),
        (["--param", "gn_hop_limit=256"], "expects 1 to 255, got '256'"),
    ],
)
def test_bad_geonetworking_options_are_one_line(words: list[str], needle: str) -> None:
    assert_bad_input(run(extra=words, timeout=60), needle)
