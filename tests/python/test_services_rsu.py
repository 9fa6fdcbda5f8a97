"""Roadside units end to end on a generated grid: a unit placed in the services file and units on
the SUMO POIs of a type send CAMs every second (RsuCaService) that reach the vehicles within the
disc's range and no others (checked against SUMO's FCD output), and a unit announces an event by
DENM (RsuDenService) from `from` to `until`, taken only by vehicles inside its area. Counted in the
summary and traced like vehicles' messages."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from sbsim.messages import read_message_lines
from sbsim.runner import run
from sbsim.scenarios.grid import make_grid
from sbsim_helpers import assert_bad_input, assert_no_crash, message_counts, read_fcd

RANGE = 300.0  # --v2x-range
AREA = 250.0  # the DENM's destination circle
UNIT = (300.0, 300.0)  # rsu0, the grid's centre (4 x 4 junctions, 200 m apart)
POIS = {"poi-a": (0.0, 0.0), "poi-b": (600.0, 600.0)}

SERVICES = f"""<services>
    <service type="artery.application.CaService"/>
    <rsu id="rsu0" x="{UNIT[0]:g}" y="{UNIT[1]:g}">
        <service type="artery.application.RsuCaService"/>
        <service type="RsuDenService" cause="3" subcause="0" from="20" until="80" interval="1" area="{AREA:g}"/>
    </rsu>
    <rsu poiType="rsu"><service type="RsuCaService"/></rsu>
</services>"""


@pytest.fixture(scope="module")
def grid(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("rsu")
    cfg = make_grid(folder, grid=4, end=100.0, seed=5, period=1.0, additional_files="rsu.poi.xml")
    pois = "".join(f'<poi id="{p}" type="rsu" x="{x:g}" y="{y:g}" color="1,0,0"/>' for p, (x, y) in POIS.items())
    (folder / "rsu.poi.xml").write_text(f'<additional>{pois}<poi id="tree" type="tree" x="100" y="5"/></additional>')
    return cfg


def test_roadside_units_send_cams_and_a_denm_to_the_vehicles_in_range(grid: Path, tmp_path: Path) -> None:
    services, messages, fcd_file = tmp_path / "services.xml", tmp_path / "messages.jsonl", tmp_path / "fcd.xml"
    services.write_text(SERVICES)
    result = run(
        grid,
        sumo_options=[f"--fcd-output {fcd_file}", "--precision 3"],
        extra=["--services", str(services), "--messages", str(messages), "--v2x-range", f"{RANGE:g}"],
        timeout=300,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    assert "roadside units: 3" in result.stdout
    fcd = read_fcd(fcd_file, step=1.0)
    lines = read_message_lines(messages)
    units = {"rsu0": UNIT, **POIS}

    # Every unit: a CAM at its first trigger (its own clock: within the first 0.1 s), then every
    # second, from its own position.
    firsts = set()
    for unit, (x, y) in units.items():
        tx = [m for m in lines if m["event"] == "tx" and m["type"] == "CAM" and m["station"] == unit]
        first = tx[0]["t"]
        assert 0 < first <= 0.1
        firsts.add(first)
        assert [m["t"] for m in tx] == pytest.approx([first + k for k in range(len(tx))])
        assert len(tx) == 100
        assert all((m["x"], m["y"]) == (x, y) and m["bytes"] == 24 for m in tx)
    assert len(firsts) == len(units), "each unit on a clock of its own"

    # rsu0's CAMs reach the vehicles within range of it at the last SUMO step, and none further.
    rx: dict[int, set[str]] = {}
    for m in lines:
        if m["event"] == "rx" and m["type"] == "CAM" and m["sender"] == "rsu0":
            rx.setdefault(m["seq"], set()).add(m["station"])
            assert m["distance"] <= RANGE
    sent = [m for m in lines if m["event"] == "tx" and m["type"] == "CAM" and m["station"] == "rsu0"]
    reached = 0
    for m in sent:
        step = float(math.floor(m["t"]))
        near = {v for v in fcd.running.get(step, set()) if math.dist(fcd.pos[v][step], UNIT) <= RANGE - 0.5}
        far = {v for v in fcd.running.get(step, set()) if math.dist(fcd.pos[v][step], UNIT) > RANGE + 0.5}
        got = rx.get(m["seq"], set())
        assert near <= got, (m["t"], near - got)
        assert not (got & far), (m["t"], got & far)
        reached += len(got)
    assert reached > 200  # not vacuous
    # The units hear each other only within range: rsu0 is 424 m from the POI units.
    assert not any(m["event"] == "rx" and m["station"] in units and m["sender"] in units for m in lines)

    # rsu0's DENM: new at 20 s, sent every second, cancelled at 80 s; taken only inside its area.
    denm = [m for m in lines if m["event"] == "denm"]
    assert [(m["t"], m["phase"]) for m in denm if m["station"] == "rsu0"] == [(20, "new"), (80, "terminate")]
    # Its own transmissions (vehicles inside the area forward them too: GeoNetworking).
    denm_tx = [m["t"] for m in lines if m["event"] == "tx" and m["type"] == "DENM" and m["station"] == "rsu0"]
    assert all(m["source"] == "rsu0" for m in lines if m["event"] == "tx" and m["type"] == "DENM")
    assert denm_tx == pytest.approx([20.0 + k for k in range(60)] + [80.0])
    warned = {m["station"]: m["t"] for m in denm if m["phase"] == "new" and m["station"] != "rsu0"}
    assert len(warned) > 10
    for vehicle, t in warned.items():
        step = float(math.floor(t))
        assert math.dist(fcd.pos[vehicle][step], UNIT) <= AREA + 0.5, vehicle
    # Heard over the radio outside the area: taken by nobody (a vehicle first heard outside it is
    # warned only once inside).
    phase_at = {(m["station"], m["t"]) for m in denm}
    outside = [
        m
        for m in lines
        if m["event"] == "rx" and m["type"] == "DENM" and m["sender"] == "rsu0" and m["distance"] > AREA + 1
    ]
    assert outside
    assert not any((m["station"], m["t"]) in phase_at for m in outside)
    counts = message_counts(result.stdout)
    assert counts["DENM"][0] == 61
    assert counts["CAM"][0] == sum(1 for m in lines if m["event"] == "tx" and m["type"] == "CAM")


def test_a_poi_type_no_poi_has_is_one_line(grid: Path, tmp_path: Path) -> None:
    services = tmp_path / "services.xml"
    services.write_text('<services><rsu poiType="lamp"><service type="RsuCaService"/></rsu></services>')
    result = run(grid, end=5.0, extra=["--services", str(services)], timeout=120)
    assert_bad_input(result, "services.xml:1", 'poiType="lamp"', "its POI types: rsu, tree")


def test_a_unit_with_a_vehicles_id_is_one_line(grid: Path, tmp_path: Path) -> None:
    services = tmp_path / "services.xml"
    services.write_text('<services><rsu id="veh0" x="0" y="0"><service type="RsuCaService"/></rsu></services>')
    result = run(grid, end=5.0, extra=["--services", str(services)], timeout=120)
    assert_bad_input(result, "roadside unit 'veh0' has the id of a vehicle departing")
